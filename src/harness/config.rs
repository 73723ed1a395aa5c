//! Benchmark configuration: a TOML file naming instance families × parameters × seeds,
//! algorithms, and exact objectives with a size cutoff and a time limit each. Lists expand into
//! every combination. Every key is checked before any job runs; an error names the key.
//!
//! ```toml
//! name = "ci"          # suite name, part of the run id
//! seed = 1             # master seed: instance seeds derive from it, the family, the
//!                      # parameters and the index, never from scheduling order
//!
//! [[family]]
//! family = "random-simple"
//! n = [16, 32]         # a scalar or a list; lists expand into every combination
//! no_cut = true
//! count = 3            # instances per parameter combination
//! algorithms = ["tsp65"]   # optional; default: every registered algorithm whose
//!                          # preconditions hold on the instance
//!
//! [[files]]            # existing instances: every .grid / .wkt file of a folder
//! dir = "instances/fixtures"
//! family = "fixtures"  # the family column of their rows
//!
//! [[exact]]
//! objective = "length" # length, cc-turns, turns, weighted, lawn-tsp
//! max_n = 64           # only instances with at most this many pixels
//! time_limit = 20      # seconds per solve
//! turn_cost = 2        # weighted only: length + turn_cost · turns
//!
//! [options]            # algorithm options; lists expand into every combination
//! merge = ["smart", "naive"]   # cycle cover → tour merging (default smart)
//! cutter = "square"            # lawn cutter: square, square-free, disk (default square)
//! coverage4 = [false, true]    # rewrite tours to cover each pixel at most 4 times
//!
//! [[algorithm]]        # an outside algorithm: any program (see crate::outside)
//! name = "my-greedy"
//! command = ["python3", "my_greedy.py", "{instance}", "{tour_out}"]
//! objectives = ["length", "turns"]
//! guarantee = { objective = "turns", factor = "7/2", against = "opt" }   # optional
//! time_limit = 60
//! ```
//!
//! Each algorithm runs once per distinct combination of the options that concern it (merge
//! and coverage4 for cycle-cover algorithms, coverage4 for tours, cutter for lawn tours); rows
//! record the options in the `merge`, `cutter` and `coverage4` columns, and a run with
//! non-default options is named `NAME[merge=naive,coverage4]` in the `algorithm` column, so
//! statistics never mix variants.

use crate::algorithms::{Cutter, Merge, Options};
use crate::error::{Error, Result};
use crate::generate::{Family, GenParams, PARAMS, Param, ParamKind, ParamValue};
use crate::outside::{OutsideAlgorithm, OutsideSpec};
use serde::{Deserialize, Deserializer, Serialize};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// A whole benchmark configuration.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Config {
    pub name: String,
    #[serde(default = "default_seed")]
    pub seed: u64,
    #[serde(default)]
    pub family: Vec<FamilySpec>,
    #[serde(default)]
    pub files: Vec<FilesSpec>,
    #[serde(default)]
    pub exact: Vec<ExactSpec>,
    /// Algorithm options; lists expand into every combination, and each algorithm runs once
    /// per distinct combination of the options that concern it.
    #[serde(default)]
    pub options: OptionsSpec,
    /// Outside algorithms (programs run per instance; see [`crate::outside`]).
    #[serde(default)]
    pub algorithm: Vec<OutsideSpec>,
    /// The folder outside algorithms run in: the config file's folder (not part of the file).
    #[serde(skip)]
    pub dir: PathBuf,
}

/// The `[options]` table: `merge`, `cutter`, `coverage4`, each a value or a list.
#[derive(Clone, Debug, Default, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct OptionsSpec {
    /// naive or smart (default smart).
    #[serde(default)]
    pub merge: OneOrMany<String>,
    /// square, square-free or disk (default square).
    #[serde(default)]
    pub cutter: OneOrMany<String>,
    /// Rewrite tours to cover each pixel at most 4 times (default false).
    #[serde(default)]
    pub coverage4: OneOrMany<bool>,
}

fn default_seed() -> u64 {
    1
}

fn default_count() -> usize {
    1
}

/// One generated family with parameter lists. Its keys are `family`, `count`, `algorithms`
/// and the names of the generator's [`PARAMS`]; any other key is an error naming it.
#[derive(Clone, Debug)]
pub struct FamilySpec {
    pub family: String,
    /// The given parameter lists (a scalar is a list of one), in the order of [`PARAMS`].
    pub params: BTreeMap<Param, Vec<ParamValue>>,
    /// Instances per parameter combination.
    pub count: usize,
    pub algorithms: Option<Vec<String>>,
}

/// A key of a `[[family]]` table. Deserializing it checks the name, so that an unknown key is
/// reported at its own line and column.
enum FamilyKey {
    Family,
    Count,
    Algorithms,
    Param(Param),
}

impl<'de> Deserialize<'de> for FamilyKey {
    fn deserialize<D: Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        let key = String::deserialize(d)?;
        Ok(match key.as_str() {
            "family" => FamilyKey::Family,
            "count" => FamilyKey::Count,
            "algorithms" => FamilyKey::Algorithms,
            _ => FamilyKey::Param(Param::from_name(&key).ok_or_else(|| {
                let keys: Vec<&str> = ["family", "count", "algorithms"]
                    .into_iter()
                    .chain(PARAMS.iter().map(|s| s.name))
                    .collect();
                serde::de::Error::custom(format!(
                    "unknown field `{key}`, expected one of {}",
                    keys.join(", ")
                ))
            })?),
        })
    }
}

impl<'de> Deserialize<'de> for FamilySpec {
    fn deserialize<D: Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        struct Table;
        impl<'de> serde::de::Visitor<'de> for Table {
            type Value = FamilySpec;

            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a [[family]] table")
            }

            fn visit_map<A: serde::de::MapAccess<'de>>(
                self,
                mut map: A,
            ) -> std::result::Result<FamilySpec, A::Error> {
                let mut family = None;
                let mut spec = FamilySpec {
                    family: String::new(),
                    params: BTreeMap::new(),
                    count: default_count(),
                    algorithms: None,
                };
                while let Some(key) = map.next_key::<FamilyKey>()? {
                    match key {
                        FamilyKey::Family => family = Some(map.next_value::<String>()?),
                        FamilyKey::Count => spec.count = map.next_value()?,
                        FamilyKey::Algorithms => spec.algorithms = Some(map.next_value()?),
                        FamilyKey::Param(param) => {
                            let values: Vec<ParamValue> = match param.spec().kind {
                                ParamKind::Count => map
                                    .next_value::<OneOrMany<usize>>()?
                                    .0
                                    .into_iter()
                                    .map(ParamValue::Count)
                                    .collect(),
                                ParamKind::Flag => map
                                    .next_value::<OneOrMany<bool>>()?
                                    .0
                                    .into_iter()
                                    .map(ParamValue::Flag)
                                    .collect(),
                                ParamKind::Fraction => map
                                    .next_value::<OneOrMany<f64>>()?
                                    .0
                                    .into_iter()
                                    .map(ParamValue::Fraction)
                                    .collect(),
                                ParamKind::Style => map
                                    .next_value::<OneOrMany<String>>()?
                                    .0
                                    .iter()
                                    .map(|s| s.parse().map(ParamValue::Style))
                                    .collect::<Result<_>>()
                                    .map_err(|e| {
                                        serde::de::Error::custom(format!("{}: {e}", param.name()))
                                    })?,
                            };
                            spec.params.insert(param, values);
                        }
                    }
                }
                spec.family = family.ok_or_else(|| serde::de::Error::missing_field("family"))?;
                Ok(spec)
            }
        }
        d.deserialize_map(Table)
    }
}

/// As in the file: `family`, every parameter of [`PARAMS`] (an empty list when not given),
/// `count`, `algorithms`; this is what the manifest records.
impl Serialize for FamilySpec {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let mut map = s.serialize_map(Some(PARAMS.len() + 3))?;
        map.serialize_entry("family", &self.family)?;
        for spec in &PARAMS {
            let values = self.params.get(&spec.param).map_or(&[][..], Vec::as_slice);
            map.serialize_entry(spec.name, values)?;
        }
        map.serialize_entry("count", &self.count)?;
        map.serialize_entry("algorithms", &self.algorithms)?;
        map.end()
    }
}

/// Existing instance files.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct FilesSpec {
    pub dir: PathBuf,
    #[serde(default)]
    pub family: Option<String>,
    #[serde(default)]
    pub algorithms: Option<Vec<String>>,
}

/// One exact objective to run on small instances.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct ExactSpec {
    pub objective: String,
    pub max_n: usize,
    pub time_limit: f64,
    #[serde(default)]
    pub turn_cost: Option<u32>,
}

/// A scalar or a list in the config; a scalar is a list of one.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(transparent)]
pub struct OneOrMany<T>(pub Vec<T>);

impl<T> Default for OneOrMany<T> {
    fn default() -> Self {
        OneOrMany(Vec::new())
    }
}

impl<'de, T: Deserialize<'de>> Deserialize<'de> for OneOrMany<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        #[derive(Deserialize)]
        #[serde(untagged)]
        enum Either<T> {
            One(T),
            Many(Vec<T>),
        }
        match Either::<T>::deserialize(d) {
            Ok(Either::One(x)) => Ok(OneOrMany(vec![x])),
            Ok(Either::Many(v)) => Ok(OneOrMany(v)),
            Err(_) => Err(serde::de::Error::custom(format!(
                "expected a {} or a list of them",
                std::any::type_name::<T>()
                    .rsplit("::")
                    .next()
                    .unwrap_or("value")
            ))),
        }
    }
}

/// One instance to generate, fully resolved.
#[derive(Clone, Debug)]
pub struct InstanceSpec {
    /// Unique, file-system safe: `family_params_iINDEX`.
    pub name: String,
    pub family: String,
    /// Canonical parameter string, e.g. `n=32 no_cut=true`.
    pub params: String,
    pub seed: u64,
    pub source: Source,
    /// Algorithms to run; `None` means all that apply.
    pub algorithms: Option<Vec<String>>,
}

#[derive(Clone, Debug)]
pub enum Source {
    Generate(GenParams),
    File(PathBuf),
}

impl Config {
    /// Reads and validates a config file. Errors name the file and the offending key.
    pub fn read(path: &Path) -> Result<Config> {
        let text = std::fs::read_to_string(path).map_err(|e| Error::io(path, e))?;
        let mut config = Config::parse(&text, &path.display().to_string())?;
        config.dir = match path.parent() {
            Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
            _ => PathBuf::from("."),
        };
        Ok(config)
    }

    /// Every combination of the `[options]` lists (one set of defaults when none is given).
    pub fn option_sets(&self) -> Vec<Options> {
        fn or_default<T: Clone>(v: &OneOrMany<T>, d: T) -> Vec<T> {
            if v.0.is_empty() { vec![d] } else { v.0.clone() }
        }
        let merges = or_default(&self.options.merge, Merge::default().to_string());
        let cutters = or_default(&self.options.cutter, Cutter::default().to_string());
        let c4s = or_default(&self.options.coverage4, false);
        let mut sets = Vec::new();
        for m in &merges {
            for c in &cutters {
                for &coverage4 in &c4s {
                    sets.push(Options {
                        // Validated in `validate`.
                        merge: m.parse().unwrap_or_default(),
                        cutter: c.parse().unwrap_or_default(),
                        coverage4,
                    });
                }
            }
        }
        sets
    }

    /// The outside algorithms of the `[[algorithm]]` tables (validated in `validate`).
    pub fn outside_algorithms(&self) -> Vec<OutsideAlgorithm> {
        self.algorithm
            .iter()
            .filter_map(|spec| OutsideAlgorithm::from_spec(spec, &self.dir).ok())
            .collect()
    }

    pub fn parse(text: &str, file: &str) -> Result<Config> {
        let config: Config = toml::from_str(text).map_err(|e| {
            let (line, column) = e
                .span()
                .map(|s| {
                    let before = &text[..s.start.min(text.len())];
                    let line = before.matches('\n').count() + 1;
                    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
                    (line, column)
                })
                .unwrap_or((1, 1));
            Error::parse(file, line, column, e.message().to_string())
        })?;
        config
            .validate()
            .map_err(|m| Error::invalid(format!("{file}: {m}")))?;
        Ok(config)
    }

    /// Checks names and values that TOML types cannot: family and algorithm names, styles,
    /// exact objectives, counts.
    fn validate(&self) -> std::result::Result<(), String> {
        if self.family.is_empty() && self.files.is_empty() {
            return Err("no instances: give at least one [[family]] or [[files]]".into());
        }
        for (i, f) in self.family.iter().enumerate() {
            let at = format!("family[{i}]");
            f.family
                .parse::<Family>()
                .map_err(|e| format!("{at}.family: {e}"))?;
            if f.count == 0 {
                return Err(format!("{at}.count: expected at least 1"));
            }
            check_algorithms(&f.algorithms, &self.algorithm, &at)?;
        }
        for (i, f) in self.files.iter().enumerate() {
            check_algorithms(&f.algorithms, &self.algorithm, &format!("files[{i}]"))?;
        }
        for m in &self.options.merge.0 {
            m.parse::<Merge>()
                .map_err(|e| format!("options.merge: {e}"))?;
        }
        for c in &self.options.cutter.0 {
            c.parse::<Cutter>()
                .map_err(|e| format!("options.cutter: {e}"))?;
        }
        let mut outside_names = std::collections::BTreeSet::new();
        for (i, a) in self.algorithm.iter().enumerate() {
            OutsideAlgorithm::from_spec(a, &self.dir)
                .map_err(|e| format!("algorithm[{i}] ({}): {e}", a.name))?;
            if !outside_names.insert(a.name.clone()) {
                return Err(format!(
                    "algorithm[{i}]: a second algorithm named {:?}",
                    a.name
                ));
            }
        }
        for (i, e) in self.exact.iter().enumerate() {
            let at = format!("exact[{i}]");
            e.objective
                .parse::<crate::exact::Objective>()
                .map_err(|err| format!("{at}.objective: {err}"))?;
            crate::exact::Objective::parse(&e.objective, e.turn_cost)
                .map_err(|err| format!("{at}.turn_cost: {err}"))?;
            if e.time_limit.is_nan() || e.time_limit <= 0.0 {
                return Err(format!(
                    "{at}.time_limit: expected a positive number of seconds"
                ));
            }
        }
        Ok(())
    }

    /// Every instance of the suite, in a deterministic order.
    pub fn instances(&self) -> Result<Vec<InstanceSpec>> {
        let mut out = Vec::new();
        for f in &self.family {
            let family: Family = f.family.parse()?;
            for combo in expand(f) {
                let params = combo
                    .iter()
                    .map(|(k, v)| format!("{}={v}", k.name()))
                    .collect::<Vec<_>>()
                    .join(" ");
                for index in 0..f.count {
                    let seed = derive_seed(self.seed, &f.family, &params, index);
                    let mut g = GenParams::new(family, seed);
                    for &(k, v) in &combo {
                        g.set(k, v)?;
                    }
                    let slug: String = params
                        .chars()
                        .filter(|&c| c != '=')
                        .map(|c| {
                            if c.is_ascii_alphanumeric() || c == '.' || c == '-' {
                                c
                            } else {
                                '_'
                            }
                        })
                        .collect();
                    let name = if slug.is_empty() {
                        format!("{}_i{index:03}", f.family)
                    } else {
                        format!("{}_{}_i{index:03}", f.family, slug)
                    };
                    out.push(InstanceSpec {
                        name,
                        family: f.family.clone(),
                        params: params.clone(),
                        seed,
                        source: Source::Generate(g),
                        algorithms: f.algorithms.clone(),
                    });
                }
            }
        }
        for f in &self.files {
            let mut files: Vec<PathBuf> = std::fs::read_dir(&f.dir)
                .map_err(|e| Error::io(&f.dir, e))?
                .filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|p| p.extension().is_some_and(|x| x == "grid" || x == "wkt"))
                .collect();
            files.sort();
            let family = f.family.clone().unwrap_or_else(|| "files".to_string());
            for p in files {
                let stem = p
                    .file_stem()
                    .map(|s| s.to_string_lossy().into_owned())
                    .unwrap_or_default();
                out.push(InstanceSpec {
                    name: format!("{family}_{stem}"),
                    family: family.clone(),
                    params: format!("file={}", p.display()),
                    seed: 0,
                    source: Source::File(p),
                    algorithms: f.algorithms.clone(),
                });
            }
        }
        let mut names: Vec<&str> = out.iter().map(|s| s.name.as_str()).collect();
        names.sort_unstable();
        if let Some(w) = names.windows(2).find(|w| w[0] == w[1]) {
            return Err(Error::invalid(format!(
                "two instances are both named {}",
                w[0]
            )));
        }
        Ok(out)
    }
}

fn check_algorithms(
    algos: &Option<Vec<String>>,
    outside: &[OutsideSpec],
    at: &str,
) -> std::result::Result<(), String> {
    for a in algos.iter().flatten() {
        if crate::algorithms::find(a).is_none() && !outside.iter().any(|o| &o.name == a) {
            return Err(format!(
                "{at}.algorithms: unknown algorithm {a:?}; registered: {}",
                crate::algorithms::names().join(", ")
            ));
        }
    }
    Ok(())
}

/// The cartesian product of the given parameter lists, in the order of [`PARAMS`] (the order of
/// the `params` column, from which seeds derive).
fn expand(f: &FamilySpec) -> Vec<Vec<(Param, ParamValue)>> {
    let mut combos: Vec<Vec<(Param, ParamValue)>> = vec![Vec::new()];
    for (&param, values) in f.params.iter().filter(|(_, v)| !v.is_empty()) {
        combos = combos
            .into_iter()
            .flat_map(|c| {
                values.iter().map(move |&v| {
                    let mut c = c.clone();
                    c.push((param, v));
                    c
                })
            })
            .collect();
    }
    combos
}

/// A job's seed: a stable hash of the master seed, family, parameters and index.
pub fn derive_seed(master: u64, family: &str, params: &str, index: usize) -> u64 {
    use sha2::{Digest, Sha256};
    let digest = Sha256::digest(format!("{master}/{family}/{params}/{index}").as_bytes());
    u64::from_le_bytes(digest[..8].try_into().expect("8 bytes"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lists_expand_into_every_combination() {
        let c = Config::parse(
            "name = \"t\"\n[[family]]\nfamily = \"rect\"\nwidth = [2, 3]\nheight = [4, 5, 6]\ncount = 2\n",
            "t.toml",
        )
        .unwrap();
        let inst = c.instances().unwrap();
        assert_eq!(inst.len(), 12);
        assert_eq!(inst[0].params, "width=2 height=4");
        assert_eq!(inst[0].name, "rect_width2_height4_i000");
        // Seeds depend on parameters and index only.
        assert_ne!(inst[0].seed, inst[1].seed);
        assert_eq!(inst[0].seed, derive_seed(1, "rect", "width=2 height=4", 0));
    }

    #[test]
    fn malformed_configs_name_the_key() {
        let bad = [
            (
                "name = \"t\"\n[[family]]\nfamily = \"rect\"\nwidht = 3\n",
                "widht",
            ),
            (
                "name = \"t\"\n[[family]]\nfamily = \"blob\"\n",
                "family[0].family",
            ),
            (
                "name = \"t\"\n[[family]]\nfamily = \"rect\"\nn = \"x\"\n",
                "expected a usize or a list",
            ),
            (
                "name = \"t\"\n[[family]]\nfamily = \"rect\"\nalgorithms = [\"nope\"]\n",
                "family[0].algorithms",
            ),
            (
                "name = \"t\"\n[[family]]\nfamily = \"rect\"\n[[exact]]\nobjective = \"len\"\nmax_n = 3\ntime_limit = 1\n",
                "exact[0].objective",
            ),
            (
                "name = \"t\"\n[[family]]\nfamily = \"rect\"\n[[exact]]\nobjective = \"length\"\ntime_limit = 1\n",
                "max_n",
            ),
            ("name = \"t\"\n", "no instances"),
        ];
        for (text, needle) in bad {
            let e = Config::parse(text, "bad.toml").unwrap_err().to_string();
            assert!(
                e.contains(needle) && e.contains("bad.toml"),
                "{needle}: {e}"
            );
        }
    }

    #[test]
    fn params_keep_their_order_and_serialize_for_the_manifest() {
        let c = Config::parse(
            "name = \"t\"\n[[family]]\nfamily = \"random-holed\"\nno_cut = true\nstyle = [\"blob\", \"snake\"]\ncompactness = 1\nn = 40\n",
            "t.toml",
        )
        .unwrap();
        let inst = c.instances().unwrap();
        assert_eq!(inst.len(), 2);
        assert_eq!(inst[0].params, "n=40 style=blob compactness=1 no_cut=true");
        let v = serde_json::to_value(&c.family[0]).unwrap();
        assert_eq!(v["n"], serde_json::json!([40]));
        assert_eq!(v["style"], serde_json::json!(["blob", "snake"]));
        assert_eq!(v["no_cut"], serde_json::json!([true]));
        assert_eq!(v["holes"], serde_json::json!([]));
        assert_eq!(v["count"], serde_json::json!(1));
    }
}
