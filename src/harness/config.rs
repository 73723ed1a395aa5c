//! Benchmark configuration: a TOML file naming instance families × parameters × seeds,
//! algorithms, and exact objectives with a size cutoff and a time limit each. Lists expand into
//! every combination. Every key and value is checked before any job runs (nothing is written
//! and nothing runs on a refused config); an error names the file, the line and column, the
//! key (`family[0].n[1]`) and what was expected, and `mowmill bench` exits with code 2.
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
//! [[family]]
//! family = "voxel"     # the discrete families voxel (n, holes), hex, honeycomb, plane (n):
//! n = [20, 40]         # discrete instances, run by the algorithms with a discrete run
//! count = 3
//!
//! [[family]]
//! family = "ortho-perturbed"  # orthogonal polygons with arbitrary coordinates:
//! n = [12, 24]         # ortho-perturbed, ortho-holed, ortho-sliver, ortho-narrow (n); run
//! count = 3            # by the algorithms with an ortho run (corollary4, strips-contour)
//!
//! [[files]]            # existing instances: every .grid/.wkt/.poly/.gg/.csv file of a folder, and
//!                      # the discrete .dm/.vox/.hex (not .json: folders hold tours as .json);
//!                      # a .wkt with a non-integral coordinate is an orthogonal polygon
//! dir = "../instances/fixtures"   # relative to the config file's folder
//! family = "fixtures"  # the family column of their rows
//!
//! [[exact]]
//! objective = "length" # length, cc-turns, turns, weighted, weighted-cc, lawn-tsp
//! max_n = 64           # only instances with at most this many pixels (vertices); lawn-tsp
//!                      # only on grid regions (discrete instances have no lawn model)
//! time_limit = 20      # seconds per solve
//! turn_cost = 2        # weighted(-cc) only: length + turn_cost · turns; the milling
//!                      # algorithms then report weighted(-cc)-c2 too
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
//!
//! # What is accepted
//!
//! * Unknown or misspelled keys, anywhere, are refused (at the key).
//! * `name`: non-empty, without `/`, `\`, a leading `.` or control characters (it becomes a
//!   folder name).
//! * `[[family]]`: `family` one of the generator's families; each parameter one the family
//!   takes (see `mowmill gen --help`), every value in the range of its row of [`PARAMS`]
//!   ([`ParamSpec::check`](crate::generate::ParamSpec::check), the check `mowmill gen` uses):
//!   `n`, `width`, `height`, `k`, `parts` from 1, `side` from 3, `holes` and `s` from 0, all
//!   up to the generator's limit of [`MAX_PIXELS`](crate::generate::MAX_PIXELS) pixels (`s` ≤ 259737); `compactness` a
//!   number in [0, 1]; `style` a style name; `no_cut` true or false. An empty list is the same
//!   as leaving the key out (the manifest records parameters not given so), so a required
//!   parameter given as `[]` is refused. Every combination is then checked as `mowmill gen`
//!   would check it ([`generate::check`]: pixel limits of `width × height`, holes that do not
//!   fit in `n`, `side ≥ 2k + 1`, ...), before any instance is generated. `count` is from 1 to
//!   [`MAX_INSTANCES`], and so is the whole suite. Two tables may name the same family, but
//!   not the same parameter combination (the same seeds and names twice).
//! * `[[files]]`: `dir` is resolved against the config file's folder (as outside algorithms'
//!   commands run there) and must hold at least one instance file (`.grid`, `.wkt`, `.poly`,
//!   `.gg` or `.csv`); `family` (default
//!   `files`) obeys the rule of `name` and is not the family of a `[[family]]` table.
//! * `algorithms` lists: registered names or the names of `[[algorithm]]` tables.
//! * `[[exact]]`: `objective` one of length, cc-turns, turns, weighted, weighted-cc, lawn-tsp, at most one
//!   table per objective (and turn cost); `turn_cost` for weighted(-cc) only and required there;
//!   `max_n` ≥ 1; `time_limit` a number of seconds in (0, [`MAX_TIME_LIMIT`]]; the same
//!   bounds for the `time_limit` of an `[[algorithm]]`, whose `memory_limit` is a number of
//!   bytes, a size such as `"4 GiB"` or `"unlimited"` (default 4 GiB).
//! * A suite without any instance is refused.

use crate::algorithms::{Cutter, Merge, Options};
use crate::error::{Error, Result};
use crate::generate::{self, Family, GenParams, PARAMS, Param, ParamKind, ParamValue};
use crate::outside::{OutsideAlgorithm, OutsideSpec};
use serde::{Deserialize, Deserializer, Serialize};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// The most instances a suite may have (and the most per parameter combination): far above
/// the suites of `experiments/` (validate has about 2·10^4), far below a count that would
/// exhaust memory before the first job.
pub const MAX_INSTANCES: usize = 1_000_000;

/// The longest time limit (seconds) of an exact objective or an outside algorithm: 30 days.
/// Anything longer is a typo, and near 1.8·10^19 s the timers themselves overflow.
pub const MAX_TIME_LIMIT: f64 = 2_592_000.0;

/// The largest config file accepted (bytes): the shipped suites are a few kB; a config is
/// copied into every manifest, so a huge one would be copied into every output too.
pub const MAX_CONFIG_BYTES: usize = 1 << 20;

/// The longest suite `name` or `[[files]]` family (characters): each becomes part of file and
/// folder names, run ids and every row of `results.csv`.
pub const MAX_NAME_CHARS: usize = 200;

/// Reads a config file of at most [`MAX_CONFIG_BYTES`]; a larger one (or one that is not a
/// regular file and gives more) is refused naming the file, before it is read whole.
pub fn read_text(path: &Path) -> Result<String> {
    use std::io::Read;
    let mut file = crate::input::open_regular(path, MAX_CONFIG_BYTES as u64, "a suite config")?;
    let mut bytes = Vec::new();
    file.read_to_end(&mut bytes)
        .map_err(|e| Error::io(path, e))?;
    if bytes.len() > MAX_CONFIG_BYTES {
        return Err(Error::invalid(format!(
            "{}: config larger than {MAX_CONFIG_BYTES} bytes: expected a suite config (a few kB)",
            path.display()
        )));
    }
    String::from_utf8(bytes).map_err(|e| {
        Error::invalid(format!(
            "{}: expected a UTF-8 TOML config: {e}",
            path.display()
        ))
    })
}

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
                                ParamKind::Pattern => map
                                    .next_value::<OneOrMany<String>>()?
                                    .0
                                    .iter()
                                    .map(|s| s.parse().map(ParamValue::Pattern))
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
/// `count`, `algorithms` (when given); this is what the manifest records.
impl Serialize for FamilySpec {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let mut map = s.serialize_map(Some(
            PARAMS.len() + 2 + usize::from(self.algorithms.is_some()),
        ))?;
        map.serialize_entry("family", &self.family)?;
        for spec in &PARAMS {
            let values = self.params.get(&spec.param).map_or(&[][..], Vec::as_slice);
            map.serialize_entry(spec.name, values)?;
        }
        map.serialize_entry("count", &self.count)?;
        // Left out when not given, as below: TOML has no null, and `bench --resume` re-reads
        // the recorded config as TOML.
        if let Some(algorithms) = &self.algorithms {
            map.serialize_entry("algorithms", algorithms)?;
        }
        map.end()
    }
}

/// Existing instance files.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct FilesSpec {
    pub dir: PathBuf,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub family: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub algorithms: Option<Vec<String>>,
}

/// One exact objective to run on small instances.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct ExactSpec {
    pub objective: String,
    pub max_n: usize,
    pub time_limit: f64,
    #[serde(default, skip_serializing_if = "Option::is_none")]
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
    /// A family of the discrete model ([`crate::discrete::generate::FAMILIES`]); the seed is the
    /// spec's.
    Discrete {
        family: String,
        n: usize,
        holes: Option<usize>,
        /// The structured families' second parameter (`hub-path`: hubs, `collinear-bridges`:
        /// paths).
        k: Option<usize>,
    },
    /// A family of orthogonal polygons with arbitrary coordinates ([`crate::ortho::FAMILIES`]);
    /// the seed is the spec's.
    Ortho {
        family: String,
        n: usize,
    },
    File(PathBuf),
}

impl Config {
    /// Reads and validates a config file. Relative `[[files]]` folders and outside
    /// algorithms' commands are resolved against the file's folder, and the folders must hold
    /// instances. Errors name the file, line, column and the offending key.
    pub fn read(path: &Path) -> Result<Config> {
        let text = read_text(path)?;
        let dir = match path.parent() {
            Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
            _ => PathBuf::from("."),
        };
        Config::parse_in(&text, &path.display().to_string(), Some(&dir))
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
                        ..Options::default()
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

    /// Parses and validates a config given as text (`file` names it in messages). Relative
    /// paths stay relative to the current folder (`dir` is empty) and `[[files]]` folders are
    /// not read: a resumed run sets `dir` afterwards, and [`Config::instances`] reads them.
    pub fn parse(text: &str, file: &str) -> Result<Config> {
        Config::parse_in(text, file, None)
    }

    /// [`Config::parse`] for a config whose folder `dir` is known (then also checked: the
    /// `[[files]]` folders).
    pub fn parse_in(text: &str, file: &str, dir: Option<&Path>) -> Result<Config> {
        if text.len() > MAX_CONFIG_BYTES {
            return Err(Error::invalid(format!(
                "{file}: config larger than {MAX_CONFIG_BYTES} bytes: expected a suite config (a few kB)"
            )));
        }
        let mut config: Config = toml::from_str(text).map_err(|e| {
            let (line, column) = e.span().map_or((1, 1), |s| line_column(text, s.start));
            Error::parse(file, line, column, e.message().to_string())
        })?;
        if let Some(dir) = dir {
            config.dir = dir.to_path_buf();
        }
        config
            .validate(dir.is_some())
            .map_err(|p| p.into_error(text, file))?;
        Ok(config)
    }

    /// Checks names and values that TOML types cannot, in the order of the file's sections:
    /// see "What is accepted" in the module documentation. With `read_dirs`, also that every
    /// `[[files]]` folder holds instances.
    fn validate(&self, read_dirs: bool) -> std::result::Result<(), Problem> {
        check_file_name(&self.name).map_err(|m| Problem::value("name", m))?;
        if self.family.is_empty() && self.files.is_empty() {
            return Err(Problem::value(
                "",
                "no instances: give at least one [[family]] or [[files]]",
            ));
        }
        let outside: Vec<&str> = self.algorithm.iter().map(|a| a.name.as_str()).collect();
        let mut total = 0usize;
        // Which table first gave each (family, parameters) combination.
        let mut combinations: BTreeMap<(String, String), usize> = BTreeMap::new();
        for (i, f) in self.family.iter().enumerate() {
            let at = format!("family[{i}]");
            if is_discrete_family(&f.family) || is_ortho_family(&f.family) {
                total = self.validate_model_family(f, &at, total, &mut combinations)?;
                check_algorithms(&f.algorithms, &outside, &at)?;
                continue;
            }
            let family: Family = f.family.parse().map_err(|e| {
                Problem::value(
                    format!("{at}.family"),
                    format!(
                        "{e}; or a family of the discrete model: {}; or of orthogonal polygons: {}",
                        crate::discrete::generate::FAMILIES.join(", "),
                        crate::ortho::FAMILIES.join(", ")
                    ),
                )
            })?;
            let info = family.info();
            for (&param, values) in &f.params {
                let key = format!("{at}.{}", param.name());
                if values.is_empty() {
                    // `[]` means "not given", as the manifest records it; required ones below.
                    continue;
                }
                info.check_takes(param).map_err(|e| Problem::key(&key, e))?;
                for (j, &v) in values.iter().enumerate() {
                    param
                        .spec()
                        .check(v)
                        .map_err(|e| Problem::value(format!("{key}[{j}]"), e))?;
                }
            }
            let given = |q: Param| f.params.get(&q).is_some_and(|v| !v.is_empty());
            info.check_required(given).map_err(|e| {
                // At the `[]` that gives no value, or at the table when the key is missing.
                match info
                    .required
                    .iter()
                    .find(|&&q| f.params.contains_key(&q) && !given(q))
                {
                    Some(q) => Problem::value(
                        format!("{at}.{}", q.name()),
                        format!("{e}: `[]` gives no value"),
                    ),
                    None => Problem::value(&at, e),
                }
            })?;
            total = count_instances(f, &at, total)?;
            for combo in expand(f) {
                let params = params_string(&combo);
                // The seed does not decide refusals; the one of the first instance is at hand.
                let mut g = GenParams::new(family, derive_seed(self.seed, &f.family, &params, 0));
                for &(k, v) in &combo {
                    g.set(k, v).map_err(|e| Problem::value(&at, e))?;
                }
                generate::check(&g).map_err(|e| Problem::value(&at, format!("{params}: {e}")))?;
                record_combination(&mut combinations, &f.family, &params, i, &at)?;
            }
            check_algorithms(&f.algorithms, &outside, &at)?;
        }
        // Which table first gave each instance name `FAMILY_STEM`.
        let mut file_names: BTreeMap<String, usize> = BTreeMap::new();
        for (i, f) in self.files.iter().enumerate() {
            let at = format!("files[{i}]");
            let family = f.family.as_deref().unwrap_or("files");
            check_file_name(family).map_err(|m| Problem::value(format!("{at}.family"), m))?;
            if self.family.iter().any(|g| g.family == family) {
                return Err(Problem::value(
                    format!("{at}.family"),
                    format!(
                        "{family:?} is also a [[family]] of this suite: the files' rows would mix with the \
                         generated ones in its statistics; name the files' family apart"
                    ),
                ));
            }
            check_algorithms(&f.algorithms, &outside, &at)?;
            if read_dirs {
                let files = instance_files(&self.dir.join(&f.dir))
                    .map_err(|e| Problem::value(format!("{at}.dir"), e))?;
                for p in files {
                    let stem = p.file_stem().unwrap_or_default().to_string_lossy();
                    let name = format!("{family}_{stem}");
                    if let Some(first) = file_names.insert(name.clone(), i) {
                        return Err(Problem::value(
                            format!("{at}.dir"),
                            format!(
                                "{} gives the instance name {name} a second time (also from files[{first}]): \
                                 name the families apart or rename the file",
                                p.display()
                            ),
                        ));
                    }
                }
            }
        }
        for (j, m) in self.options.merge.0.iter().enumerate() {
            m.parse::<Merge>()
                .map_err(|e| Problem::value(format!("options.merge[{j}]"), e))?;
        }
        for (j, c) in self.options.cutter.0.iter().enumerate() {
            c.parse::<Cutter>()
                .map_err(|e| Problem::value(format!("options.cutter[{j}]"), e))?;
        }
        let mut outside_names = std::collections::BTreeSet::new();
        for (i, a) in self.algorithm.iter().enumerate() {
            let at = format!("algorithm[{i}]");
            check_time_limit(a.time_limit)
                .map_err(|m| Problem::value(format!("{at}.time_limit"), m))?;
            OutsideAlgorithm::from_spec(a, &self.dir).map_err(|e| {
                // Its messages start with the key at fault (`command: ...`).
                let key = e.split_once(':').map(|(k, _)| k).filter(|k| {
                    k.chars()
                        .all(|c| c.is_ascii_lowercase() || c == '_' || c == '.')
                });
                match (key, e.split_once(':')) {
                    (Some(k), Some((_, rest))) => Problem::value(format!("{at}.{k}"), rest.trim()),
                    _ => Problem::value(format!("{at}.name"), e),
                }
            })?;
            let mut objectives_seen: Vec<crate::algorithms::Objective> = Vec::new();
            for (j, o) in a.objectives.iter().enumerate() {
                let Ok(objective) = o.parse::<crate::algorithms::Objective>() else {
                    continue;
                };
                if objectives_seen.contains(&objective) {
                    return Err(Problem::value(
                        format!("{at}.objectives[{j}]"),
                        format!("objective {o:?} is listed twice: its rows would be written twice"),
                    ));
                }
                objectives_seen.push(objective);
            }
            if !outside_names.insert(a.name.clone()) {
                return Err(Problem::value(
                    format!("{at}.name"),
                    format!("a second algorithm named {:?}", a.name),
                ));
            }
        }
        let mut objectives = Vec::new();
        for (i, e) in self.exact.iter().enumerate() {
            let at = format!("exact[{i}]");
            let names = crate::exact::Objective::EXACT_NAMES;
            if !names.contains(&crate::algorithms::canonical_objective(&e.objective)) {
                return Err(Problem::value(
                    format!("{at}.objective"),
                    format!(
                        "unknown objective {:?}: expected one of {}",
                        e.objective,
                        names.join(", ")
                    ),
                ));
            }
            let objective =
                crate::exact::Objective::parse(&e.objective, e.turn_cost).map_err(|err| {
                    // At `turn_cost` when given, else at the table that lacks it.
                    let key = if e.turn_cost.is_some() {
                        format!("{at}.turn_cost")
                    } else {
                        at.clone()
                    };
                    // Its message speaks of the command line's flag.
                    let err = err
                        .replace("--turn-cost C", "turn_cost = C")
                        .replace("--turn-cost", "turn_cost");
                    Problem::value(key, err)
                })?;
            if e.max_n == 0 {
                return Err(Problem::value(
                    format!("{at}.max_n"),
                    "expected at least 1 (the largest number of pixels to solve exactly)",
                ));
            }
            check_time_limit(e.time_limit)
                .map_err(|m| Problem::value(format!("{at}.time_limit"), m))?;
            if let Some(first) = objectives.iter().position(|&o| o == objective) {
                return Err(Problem::value(
                    &at,
                    format!(
                        "objective {} is also solved by exact[{first}]: its rows would be written twice",
                        e.objective
                    ),
                ));
            }
            objectives.push(objective);
        }
        Ok(())
    }

    /// Every instance of the suite, in a deterministic order.
    pub fn instances(&self) -> Result<Vec<InstanceSpec>> {
        let mut out = Vec::new();
        for f in &self.family {
            let discrete = is_discrete_family(&f.family);
            let ortho = is_ortho_family(&f.family);
            for combo in expand(f) {
                let params = params_string(&combo);
                for index in 0..f.count {
                    let seed = derive_seed(self.seed, &f.family, &params, index);
                    let source = if discrete {
                        let (n, holes, k) = discrete_params(&combo);
                        Source::Discrete {
                            family: f.family.clone(),
                            n: n.unwrap_or(0),
                            holes,
                            k,
                        }
                    } else if ortho {
                        Source::Ortho {
                            family: f.family.clone(),
                            n: discrete_params(&combo).0.unwrap_or(0),
                        }
                    } else {
                        let mut g = GenParams::new(f.family.parse::<Family>()?, seed);
                        for &(k, v) in &combo {
                            g.set(k, v)?;
                        }
                        Source::Generate(g)
                    };
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
                        source,
                        algorithms: f.algorithms.clone(),
                    });
                }
            }
        }
        for (i, f) in self.files.iter().enumerate() {
            // Relative to the config file's folder, where outside algorithms run too.
            let files = instance_files(&self.dir.join(&f.dir))
                .map_err(|e| Error::invalid(format!("files[{i}].dir: {e}")))?;
            let family = f.family.clone().unwrap_or_else(|| "files".to_string());
            for p in files {
                let stem = p
                    .file_stem()
                    .map(|s| s.to_string_lossy().into_owned())
                    .unwrap_or_default();
                // The path as the config gives it, so that the column does not depend on
                // where the run was started.
                let given = f.dir.join(p.file_name().unwrap_or_default());
                out.push(InstanceSpec {
                    name: format!("{family}_{stem}"),
                    family: family.clone(),
                    params: format!("file={}", given.display()),
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

/// Checks a `[[family]]` table's `count` and returns the suite's instance total with its
/// instances (combinations of the parameter lists × count) added.
fn count_instances(f: &FamilySpec, at: &str, total: usize) -> std::result::Result<usize, Problem> {
    if !(1..=MAX_INSTANCES).contains(&f.count) {
        return Err(Problem::value(
            format!("{at}.count"),
            format!(
                "expected from 1 to {MAX_INSTANCES} instances per parameter combination, got {}",
                f.count
            ),
        ));
    }
    let table_instances = f
        .params
        .values()
        .filter(|v| !v.is_empty())
        .try_fold(f.count, |acc, v| acc.checked_mul(v.len()));
    match table_instances.and_then(|t| total.checked_add(t)) {
        Some(t) if t <= MAX_INSTANCES => Ok(t),
        _ => Err(Problem::value(
            at,
            format!(
                "the suite would have more than {MAX_INSTANCES} instances (combinations of the \
                 parameter lists × count)"
            ),
        )),
    }
}

/// Records that table `index` gives `family` with `params`; refuses a combination an earlier
/// table gave (the same instances, seeds and names, twice).
fn record_combination(
    combinations: &mut BTreeMap<(String, String), usize>,
    family: &str,
    params: &str,
    index: usize,
    at: &str,
) -> std::result::Result<(), Problem> {
    match combinations.insert((family.to_string(), params.to_string()), index) {
        Some(first) => Err(Problem::value(
            at,
            format!(
                "{family} {params} is also in family[{first}]: the same family and parameters give \
                 the same instances (seeds and names) twice"
            ),
        )),
        None => Ok(()),
    }
}

/// Whether `family` is a family of the discrete model (`voxel`, `hex`, `honeycomb`, `plane`).
fn is_discrete_family(family: &str) -> bool {
    crate::discrete::generate::FAMILIES.contains(&family)
}

/// Whether `family` is a family of orthogonal polygons with arbitrary coordinates
/// (`ortho-perturbed`, `ortho-holed`, `ortho-sliver`, `ortho-narrow`).
fn is_ortho_family(family: &str) -> bool {
    crate::ortho::FAMILIES.contains(&family)
}

/// The `n`, `holes` and `k` of a discrete (or ortho) family's parameter combination.
fn discrete_params(combo: &[(Param, ParamValue)]) -> (Option<usize>, Option<usize>, Option<usize>) {
    let get = |p: Param| {
        combo.iter().find_map(|&(k, v)| match (k == p, v) {
            (true, ParamValue::Count(c)) => Some(c),
            _ => None,
        })
    };
    (get(Param::N), get(Param::Holes), get(Param::K))
}

impl Config {
    /// The checks of a `[[family]]` table of a discrete or ortho family: it takes `n`
    /// (required) and, for `voxel`, `holes`, for the structured discrete families `k`
    /// (required); counts and combinations as for the grid families.
    /// Returns the new instance total.
    fn validate_model_family(
        &self,
        f: &FamilySpec,
        at: &str,
        total: usize,
        combinations: &mut BTreeMap<(String, String), usize>,
    ) -> std::result::Result<usize, Problem> {
        for (&param, values) in &f.params {
            let key = format!("{at}.{}", param.name());
            let structured = crate::discrete::generate::STRUCTURED.contains(&f.family.as_str());
            let takes = param == Param::N
                || (param == Param::Holes && f.family == "voxel")
                || (param == Param::K && structured);
            if !takes && !values.is_empty() {
                let takes = if is_discrete_family(&f.family) {
                    crate::discrete::generate::takes(&f.family)
                } else {
                    "n"
                };
                return Err(Problem::key(
                    &key,
                    Error::invalid(format!(
                        "parameter `{}` does not apply to family {} (it takes: {takes})",
                        param.name(),
                        f.family,
                    )),
                ));
            }
        }
        let total = count_instances(f, at, total)?;
        let index = at
            .trim_start_matches("family[")
            .trim_end_matches(']')
            .parse()
            .unwrap_or(0);
        for combo in expand(f) {
            let params = params_string(&combo);
            let (n, holes, k) = discrete_params(&combo);
            if is_ortho_family(&f.family) {
                match n {
                    Some(1..=10_000) => {}
                    _ => {
                        return Err(Problem::value(
                            at,
                            format!("{params}: family {} needs n from 1 to 10000", f.family),
                        ));
                    }
                }
            } else {
                crate::discrete::generate::check(&f.family, n, holes, k)
                    .map_err(|e| Problem::value(at, format!("{params}: {e}")))?;
            }
            record_combination(combinations, &f.family, &params, index, at)?;
        }
        Ok(total)
    }
}

/// Refuses an `algorithms` entry that is neither registered nor an `[[algorithm]]` table.
fn check_algorithms(
    algos: &Option<Vec<String>>,
    outside: &[&str],
    at: &str,
) -> std::result::Result<(), Problem> {
    let mut seen: Vec<&str> = Vec::new();
    for (j, a) in algos.iter().flatten().enumerate() {
        // A registered algorithm by its registered name (aliases resolve to it).
        let canonical = crate::algorithms::find(a).map_or(a.as_str(), |r| r.name);
        if seen.contains(&canonical) {
            return Err(Problem::value(
                format!("{at}.algorithms[{j}]"),
                format!("algorithm {a:?} is listed twice: its rows would be written twice"),
            ));
        }
        seen.push(canonical);
        if crate::algorithms::find(a).is_none() && !outside.contains(&a.as_str()) {
            let mut known = crate::algorithms::names();
            known.extend_from_slice(outside);
            return Err(Problem::value(
                format!("{at}.algorithms[{j}]"),
                format!("unknown algorithm {a:?}; known: {}", known.join(", ")),
            ));
        }
    }
    Ok(())
}

/// Refuses a name that becomes part of a file or folder name (the suite name in the run id,
/// a `[[files]]` family in instance names) and would leave or break that folder.
fn check_file_name(name: &str) -> std::result::Result<(), String> {
    let chars = name.chars().count();
    if chars > MAX_NAME_CHARS {
        return Err(format!(
            "a name of {chars} characters: expected at most {MAX_NAME_CHARS} (it becomes part of file names and of every row)"
        ));
    }
    if name.is_empty()
        || name.starts_with('.')
        || name.contains(['/', '\\'])
        || name.chars().any(char::is_control)
    {
        return Err(format!(
            "{name:?}: expected a non-empty name without / \\, a leading . or control characters (it becomes part of file names)"
        ));
    }
    Ok(())
}

/// Refuses a time limit that is not a number of seconds in (0, [`MAX_TIME_LIMIT`]]: the one
/// check of configs' `time_limit` and of every `--time-limit` (a larger or infinite value would
/// make `Duration::from_secs_f64` panic).
pub fn check_time_limit(seconds: f64) -> std::result::Result<(), String> {
    if seconds > 0.0 && seconds <= MAX_TIME_LIMIT {
        return Ok(());
    }
    Err(format!(
        "expected a positive number of seconds, at most {MAX_TIME_LIMIT} (30 days), got {seconds:?}"
    ))
}

/// The instance files of a folder (every extension [`Instance::read`](crate::instance::Instance::read)
/// knows: `.grid`, `.wkt`, `.poly`, `.gg`, `.csv`), sorted; an error if it cannot be read or holds
/// none.
fn instance_files(dir: &Path) -> std::result::Result<Vec<PathBuf>, String> {
    let entries = std::fs::read_dir(dir).map_err(|e| {
        format!(
            "cannot read folder {}: {e} (a relative dir is relative to the config file's folder)",
            dir.display()
        )
    })?;
    let mut files: Vec<PathBuf> = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| {
            // Discrete instances by `.dm`, `.vox`, `.hex`; not `.json`, which folders of
            // instances also hold as tour files.
            crate::instance::Format::from_extension(p).is_some()
                || p.extension().and_then(|e| e.to_str()).is_some_and(|e| {
                    ["dm", "vox", "hex"].contains(&e.to_ascii_lowercase().as_str())
                })
        })
        .collect();
    // Only regular files (or links to them) are read: opening a FIFO would block for ever, a
    // device could give endless bytes.
    for p in &files {
        let meta = std::fs::metadata(p).map_err(|e| format!("cannot read {}: {e}", p.display()))?;
        if !meta.is_file() {
            let ft = meta.file_type();
            use std::os::unix::fs::FileTypeExt;
            let kind = if ft.is_fifo() {
                "a FIFO"
            } else if ft.is_dir() {
                "a folder"
            } else if ft.is_socket() {
                "a socket"
            } else if ft.is_block_device() || ft.is_char_device() {
                "a device"
            } else {
                "not a regular file"
            };
            return Err(format!(
                "{} is {kind}: expected a regular instance file (remove it or rename it)",
                p.display()
            ));
        }
    }
    if files.is_empty() {
        return Err(format!(
            "no instance file (.{}) in {}",
            crate::instance::EXTENSIONS.join(", ."),
            dir.display()
        ));
    }
    files.sort();
    Ok(files)
}

/// A value [`Config::validate`] refuses: its key path (`family[0].n[1]`, empty for the whole
/// suite), whether the key itself rather than its value is at fault, and what was expected.
#[derive(Debug)]
struct Problem {
    path: String,
    at_key: bool,
    message: String,
}

impl Problem {
    fn value(path: impl Into<String>, message: impl std::fmt::Display) -> Problem {
        Problem {
            path: path.into(),
            at_key: false,
            message: message.to_string(),
        }
    }

    fn key(path: impl Into<String>, message: impl std::fmt::Display) -> Problem {
        Problem {
            at_key: true,
            ..Problem::value(path, message)
        }
    }

    /// The error at the problem's place in `text`: `file:line:column: path: message`.
    fn into_error(self, text: &str, file: &str) -> Error {
        // The typed config parsed, so the spanned document parses too; without it (or for
        // the whole suite) the message still names the file and the key.
        let located = toml::de::DeTable::parse(text)
            .ok()
            .and_then(|doc| locate(&doc, &self.path, self.at_key));
        match located {
            Some((offset, path)) => {
                let (line, column) = line_column(text, offset);
                Error::parse(file, line, column, format!("{path}: {}", self.message))
            }
            None if self.path.is_empty() => Error::invalid(format!("{file}: {}", self.message)),
            None => Error::invalid(format!("{file}: {}: {}", self.path, self.message)),
        }
    }
}

/// The byte offset of the key path `path` (`family[0].n[1]`) in a parsed document, and the
/// path as shown: the deepest part of it present in the file (a missing key points at its
/// table, an index into a scalar at the scalar, which the shown path then leaves out).
fn locate(
    doc: &toml::Spanned<toml::de::DeTable>,
    path: &str,
    at_key: bool,
) -> Option<(usize, String)> {
    if path.is_empty() {
        return None;
    }
    let mut table = doc.get_ref();
    let mut found: Option<(usize, String)> = None;
    let mut shown = String::new();
    let parts: Vec<&str> = path.split('.').collect();
    for (p, part) in parts.iter().enumerate() {
        let (name, indices) = part.split_once('[').unwrap_or((part, ""));
        let Some((key, value)) = table.iter().find(|(k, _)| k.get_ref() == name) else {
            break;
        };
        if !shown.is_empty() {
            shown.push('.');
        }
        shown.push_str(name);
        let last = p + 1 == parts.len();
        let offset = if at_key && last && indices.is_empty() {
            key.span().start
        } else {
            value.span().start
        };
        found = Some((offset, shown.clone()));
        let mut current = value;
        for index in indices.split('[').filter(|s| !s.is_empty()) {
            let element = index
                .trim_end_matches(']')
                .parse::<usize>()
                .ok()
                .and_then(|i| current.get_ref().as_array().and_then(|a| a.get(i)));
            let Some(element) = element else { break };
            shown.push_str(&format!("[{index}"));
            found = Some((element.span().start, shown.clone()));
            current = element;
        }
        match current.get_ref().as_table() {
            Some(t) if !last => table = t,
            _ => break,
        }
    }
    found
}

/// Line and column (from 1, the column in characters) of a byte offset of `text`.
/// The 1-based line and column (in characters) of byte `offset` of `text`.
pub fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let before = &text[..offset.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}

/// The `params` column of a combination: `key=value` in the order of [`PARAMS`].
fn params_string(combo: &[(Param, ParamValue)]) -> String {
    combo
        .iter()
        .map(|(k, v)| format!("{}={v}", k.name()))
        .collect::<Vec<_>>()
        .join(" ")
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
mod tests;
