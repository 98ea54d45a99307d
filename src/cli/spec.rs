// SPDX-License-Identifier: MIT OR Apache-2.0
//! The generation parameters of every command that builds the core (`generate`,
//! `simulate`, `bench`, `synth`, `ecc-ripple`): `SpecArgs`, its options made from the
//! fields of `Spec`, the `--config` file, and the TOML of `--print-config`.

use clap::Args;
use golden::params::{ParamError, Params, Spec};
use std::path::{Path, PathBuf};

use super::Outcome;

/// Generation parameters, shared by every subcommand that builds the core: the defaults
/// (`Spec::default()`), then a TOML file (`--config`), then one option per `Spec` field
/// (`--clock-hz` for `clock_hz`, ...); a later source overrides an earlier one.
///
/// The options are made from the fields of `Spec` and [`describe`], so that a field, its
/// option, its key in a file and the line of `--print-config` cannot drift apart.
#[derive(Clone, Debug, Default)]
pub struct SpecArgs {
    /// `--config`.
    config: Option<PathBuf>,
    /// `--print-config`.
    print_config: bool,
    /// The `Spec` fields given as options, each checked to fit its field's type.
    options: toml::Table,
}

/// How a `Spec` field appears on the command line: option name, value name, and meaning,
/// unit and range (the help line and the comment in `--print-config`; the default is
/// added from `Spec::default()`). `None` for a key that is not a field.
fn describe(key: &str) -> Option<(&'static str, &'static str, String)> {
    use golden::params::{
        MAX_CHANNELS, MAX_COUNTER_BITS, MAX_LINES, MIN_COUNTER_BITS, MIN_DT_CYCLES,
    };
    Some(match key {
        "clock_hz" => (
            "clock-hz",
            "HZ",
            "Clock frequency, Hz; finite, > 0".to_string(),
        ),
        "lines" => (
            "lines",
            "K",
            format!("Encoder lines (A pulses) per revolution; 1..={MAX_LINES}"),
        ),
        "dt_cycles" => (
            "dt-cycles",
            "CYCLES",
            format!("Nominal dt, clock cycles; {MIN_DT_CYCLES}..=2^counter_bits - 1"),
        ),
        "counter_bits" => (
            "counter-bits",
            "BITS",
            format!(
                "Width of cfg_dt and of the ts/Cep/Cdt/Nep1/Ndt1 counters, bits; \
                 {MIN_COUNTER_BITS}..={MAX_COUNTER_BITS}"
            ),
        ),
        "timeout_s" => (
            "timeout-s",
            "S",
            "Zero-speed timeout, s; at least one dt, under 2^counter_bits - 1 dt".to_string(),
        ),
        "estimators" => (
            "estimators",
            "LIST",
            "Speed outputs to build, comma-separated, of n1,n2,n3,pc,et,mt; n3 is required, \
             one left out reads 0 and its hardware is not built"
                .to_string(),
        ),
        "channels" => (
            "channels",
            "N",
            format!(
                "Encoder channels of encspeed_wb, each a core with its own 256-byte register \
                 window (channel c at c * 0x100); 1..={MAX_CHANNELS}; the board tops and \
                 encspeed_ecc_wb have one"
            ),
        ),
        "identification" => (
            "no-identification",
            "",
            "Leave the online eccentricity identification out of encspeed_ecc and \
             encspeed_ecc_wb (a flag; in a file, identification = false): ident_* and \
             IDENT_* read 0, the correction runs on coefficients identified elsewhere"
                .to_string(),
        ),
        _ => return None,
    })
}

/// `Spec::default()` as a table (sorted by key).
fn default_table() -> toml::Table {
    toml::Table::try_from(Spec::default()).expect("a Spec is a flat table")
}

/// The keys of `Spec`, in field order (as its serialisation writes them).
fn spec_keys() -> Vec<String> {
    let text = toml::to_string(&Spec::default()).expect("a Spec is a flat table");
    text.lines()
        .filter_map(|l| l.split_once(" = ").map(|(k, _)| k.trim().to_string()))
        .collect()
}

/// A value as the help text shows it: `100000000`, not `100000000.0`; a list as the
/// option takes it, `n1,n2`.
fn show(v: &toml::Value) -> String {
    match v {
        toml::Value::Float(f) => f.to_string(),
        toml::Value::Array(items) => items
            .iter()
            .map(|i| i.as_str().map_or_else(|| i.to_string(), str::to_string))
            .collect::<Vec<_>>()
            .join(","),
        other => other.to_string(),
    }
}

/// `key` set to `value` alone, checked against the type of its `Spec` field.
fn check_field(key: &str, value: toml::Value) -> Result<toml::Value, String> {
    let one = toml::Table::from_iter([(key.to_string(), value.clone())]);
    toml::Value::Table(one)
        .try_into::<Spec>()
        .map(|_| value)
        // The first line; the next one (`in `key``) repeats the option's name.
        .map_err(|e| e.to_string().lines().next().unwrap_or("").to_string())
}

impl Args for SpecArgs {
    fn augment_args(cmd: clap::Command) -> clap::Command {
        use clap::{Arg, ArgAction};
        let mut cmd = cmd
            .arg(
                Arg::new("config")
                    .long("config")
                    .value_name("FILE.toml")
                    .value_parser(clap::value_parser!(PathBuf))
                    .help(
                        "TOML file of parameters: any keys of --print-config; \
                         options override it",
                    ),
            )
            .arg(
                Arg::new("print-config")
                    .long("print-config")
                    .action(ArgAction::SetTrue)
                    .help(
                        "Print the effective parameters (defaults < --config < options) \
                         as TOML and exit",
                    ),
            );
        let defaults = default_table();
        for key in spec_keys() {
            let default = &defaults[&key];
            // A field without a description has no option; a unit test sees to it.
            let Some((long, value_name, about)) = describe(&key) else {
                continue;
            };
            // A boolean field is on by default and has a flag that turns it off.
            if default.is_bool() {
                cmd = cmd.arg(
                    Arg::new(long)
                        .long(long)
                        .action(ArgAction::SetTrue)
                        .help(format!("{about} [default {key} = {}]", show(default))),
                );
                continue;
            }
            let float = default.is_float();
            let list = default.is_array();
            let field = key.clone();
            let parse = move |s: &str| -> Result<toml::Value, String> {
                let v = if list {
                    Ok(toml::Value::Array(
                        s.split(',')
                            .map(|item| toml::Value::String(item.trim().to_string()))
                            .collect(),
                    ))
                } else if float {
                    s.parse::<f64>()
                        .map(toml::Value::Float)
                        .map_err(|e| e.to_string())
                } else {
                    s.parse::<i64>()
                        .map(toml::Value::Integer)
                        .map_err(|e| e.to_string())
                }?;
                check_field(&field, v)
            };
            cmd = cmd.arg(
                Arg::new(long)
                    .long(long)
                    .value_name(value_name)
                    .allow_negative_numbers(true)
                    .value_parser(parse)
                    .help(format!("{about} [default {}]", show(default))),
            );
        }
        cmd
    }

    fn augment_args_for_update(cmd: clap::Command) -> clap::Command {
        Self::augment_args(cmd)
    }
}

impl clap::FromArgMatches for SpecArgs {
    fn from_arg_matches(m: &clap::ArgMatches) -> Result<Self, clap::Error> {
        let mut s = SpecArgs::default();
        s.update_from_arg_matches(m)?;
        Ok(s)
    }

    fn update_from_arg_matches(&mut self, m: &clap::ArgMatches) -> Result<(), clap::Error> {
        if let Some(path) = m.get_one::<PathBuf>("config") {
            self.config = Some(path.clone());
        }
        self.print_config |= m.get_flag("print-config");
        let defaults = default_table();
        for key in spec_keys() {
            if let Some((long, _, _)) = describe(&key) {
                if defaults[&key].is_bool() {
                    if m.get_flag(long) {
                        self.options.insert(key, toml::Value::Boolean(false));
                    }
                } else if let Some(v) = m.get_one::<toml::Value>(long) {
                    self.options.insert(key, v.clone());
                }
            }
        }
        Ok(())
    }
}

impl SpecArgs {
    /// The configuration file as a table, each key checked against `Spec`; empty when
    /// there is no file.
    fn file_table(&self) -> Result<toml::Table, String> {
        let Some(path) = &self.config else {
            return Ok(toml::Table::new());
        };
        let text = std::fs::read_to_string(path)
            .map_err(|e| format!("cannot read configuration file {}: {e}", path.display()))?;
        let bad = |e: toml::de::Error| format!("configuration file {}: {e}", path.display());
        // Parsed as a Spec for its messages (unknown key, wrong type, with the line), then
        // kept as a table to know which keys it sets.
        toml::from_str::<Spec>(&text).map_err(bad)?;
        toml::from_str(&text).map_err(bad)
    }

    /// Validated parameters: defaults < file < options. A refusal names the parameter and,
    /// unless it is a default, where its value came from.
    fn params(&self) -> Result<Params, String> {
        let file = self.file_table()?;
        let mut table = file.clone();
        table.extend(self.options.clone());
        let spec: Spec = toml::Value::Table(table)
            .try_into()
            .map_err(|e| format!("parameters: {e}"))?;
        Params::new(spec).map_err(|e| {
            let from: Vec<String> = fields_of(&e)
                .into_iter()
                .filter_map(|k| {
                    if self.options.contains_key(&k) {
                        let long = describe(&k).map_or(k.clone(), |d| d.0.to_string());
                        Some(format!("{k} from --{long}"))
                    } else if file.contains_key(&k) {
                        let path = self.config.as_deref().unwrap_or(Path::new(""));
                        Some(format!("{k} from {}", path.display()))
                    } else {
                        None
                    }
                })
                .collect();
            if from.is_empty() {
                e.to_string()
            } else {
                format!("{e} [{}]", from.join(", "))
            }
        })
    }

    /// Validate, then run `f`; or with `--print-config` print the parameters instead.
    pub fn run(&self, f: impl FnOnce(&Params) -> Outcome) -> Outcome {
        let p = self.params().map_err(|e| (2, e))?;
        if self.print_config {
            print!("{}", config_toml(p.spec()));
            Ok(())
        } else {
            f(&p)
        }
    }
}

/// The `Spec` fields a refusal names, in the order its message names them.
fn fields_of(e: &ParamError) -> Vec<String> {
    let msg = e.to_string();
    let ident = |c: char| c.is_ascii_alphanumeric() || c == '_';
    let mut found: Vec<(usize, String)> = spec_keys()
        .into_iter()
        .filter_map(|k| {
            let at = msg.match_indices(k.as_str()).find(|&(i, _)| {
                !msg[..i].ends_with(ident) && !msg[i + k.len()..].starts_with(ident)
            });
            at.map(|(i, _)| (i, k))
        })
        .collect();
    found.sort();
    found.into_iter().map(|(_, k)| k).collect()
}

/// `spec` as a TOML configuration file: every field after a comment line with its help.
fn config_toml(spec: &Spec) -> String {
    let defaults = default_table();
    let mut out = String::from(
        "# encspeed parameters: `encspeed generate --config FILE.toml`. Any key may be left\n\
         # out for its default; command-line options override the file.\n",
    );
    let text = toml::to_string(spec).expect("a Spec is a flat table");
    for line in text.lines() {
        let key = line.split_once(" = ").map_or("", |(k, _)| k.trim());
        let about = describe(key).map_or(String::new(), |d| d.2);
        let default = defaults.get(key).map_or(String::new(), show);
        out.push_str(&format!("\n# {about} [default {default}]\n{line}\n"));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_spec_field_has_an_option() {
        for key in spec_keys() {
            let (long, _, about) = describe(&key).unwrap_or_else(|| panic!("describe {key}"));
            // A boolean field's option is the flag that turns it off.
            assert_eq!(
                long.strip_prefix("no-").unwrap_or(long).replace('-', "_"),
                key
            );
            assert!(!about.is_empty());
        }
    }

    #[test]
    fn printed_config_is_a_spec() {
        let text = config_toml(&Spec::default());
        assert_eq!(toml::from_str::<Spec>(&text).unwrap(), Spec::default());
    }

    #[test]
    fn a_list_option_is_comma_separated_and_checked_against_its_field() {
        use clap::FromArgMatches;
        let cmd = SpecArgs::augment_args(clap::Command::new("t"));
        let m = cmd
            .clone()
            .try_get_matches_from(["t", "--estimators", "mt, n3"])
            .unwrap();
        let args = SpecArgs::from_arg_matches(&m).unwrap();
        let p = args.params().unwrap();
        use golden::params::SpeedOutput::{Mt, N3};
        assert_eq!(p.spec().estimators, [N3, Mt]);
        let e = cmd
            .clone()
            .try_get_matches_from(["t", "--estimators", "n3,rpm"])
            .unwrap_err()
            .to_string();
        assert!(e.contains("rpm"), "{e}");
        let m = cmd
            .try_get_matches_from(["t", "--estimators", "pc,et"])
            .unwrap();
        let e = SpecArgs::from_arg_matches(&m)
            .unwrap()
            .params()
            .unwrap_err();
        assert!(
            e.contains("n3 is missing") && e.contains("--estimators"),
            "{e}"
        );
    }

    #[test]
    fn no_identification_is_a_flag_that_turns_the_field_off() {
        use clap::FromArgMatches;
        let cmd = SpecArgs::augment_args(clap::Command::new("t"));
        let params = |argv: &[&str]| {
            let m = cmd.clone().try_get_matches_from(argv).unwrap();
            SpecArgs::from_arg_matches(&m).unwrap().params().unwrap()
        };
        assert!(params(&["t"]).identification());
        let off = params(&["t", "--no-identification"]);
        assert!(!off.identification());
        assert!(config_toml(off.spec()).contains("\nidentification = false\n"));
        assert!(golden::provenance::generate_command(&off).ends_with(" --no-identification"));
        // It takes no value.
        assert!(cmd
            .try_get_matches_from(["t", "--no-identification", "false"])
            .is_err());
    }

    #[test]
    fn fields_of_finds_whole_names_in_message_order() {
        let e = ParamError::DtTooWide {
            dt_cycles: 100_000,
            counter_bits: 12,
        };
        assert_eq!(fields_of(&e), ["dt_cycles", "counter_bits"]);
        assert_eq!(fields_of(&ParamError::ZeroLines), ["lines"]);
    }
}
