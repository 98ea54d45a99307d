// SPDX-License-Identifier: MIT OR Apache-2.0
//! The timing shared by the core's sequential arithmetic blocks (the speed calculator, the
//! baseline speeds, the eccentricity-corrected M/T and n3): a one-deep request register in
//! which the latest start wins, and a computation of fixed latency.
//!
//! Per rising edge, in this order:
//! 1. a running computation counts down, and on its last edge publishes its result; if none
//!    runs and a request is pending, the request begins (its result is published `latency`
//!    edges after the edge that latched it, for a start while idle);
//! 2. a start latches its request, replacing one that has not begun, so the last start is
//!    always computed;
//! 3. reset abandons the request and the computation (and publishes nothing).
//!
//! `busy` is high while a request is pending or a computation runs.

/// The request register and the computation of one block (module docs). The result of a
/// request is computed when it begins; the model publishes it on schedule.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LatestRequest<R, O> {
    request: Option<R>,
    job: Option<(u32, O)>,
}

impl<R, O> Default for LatestRequest<R, O> {
    fn default() -> Self {
        Self {
            request: None,
            job: None,
        }
    }
}

impl<R, O> LatestRequest<R, O> {
    /// Idle, nothing pending (the state after reset).
    pub fn new() -> Self {
        Self::default()
    }

    /// One rising edge (module docs): `start` is the request latched at this edge, if any;
    /// `compute` turns a request into its result when it begins. The result published at
    /// this edge, if any. Panics if `latency` < 2.
    pub fn edge(
        &mut self,
        start: Option<R>,
        reset: bool,
        latency: u32,
        compute: impl FnOnce(R) -> O,
    ) -> Option<O> {
        assert!(latency >= 2, "latency {latency} below 2 edges");
        let mut done = None;
        if let Some((remaining, _)) = &mut self.job {
            *remaining -= 1;
            if *remaining == 0 {
                done = self.job.take().map(|(_, result)| result);
            }
        } else if let Some(request) = self.request.take() {
            self.job = Some((latency - 1, compute(request)));
        }
        if let Some(request) = start {
            self.request = Some(request);
        }
        if reset {
            self.request = None;
            self.job = None;
            return None;
        }
        done
    }

    /// A request is pending or a computation runs.
    pub fn busy(&self) -> bool {
        self.request.is_some() || self.job.is_some()
    }
}
