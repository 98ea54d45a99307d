// SPDX-License-Identifier: MIT OR Apache-2.0
mod inst;
mod prefix;
mod tops;
mod waivers;
mod wb;
