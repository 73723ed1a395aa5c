//! Outside algorithms: programs in any language, declared in a config's `[[algorithm]]` table
//! (or given to `mowmill solve --command`), run as child processes on each instance. Their
//! walks go through the same [evaluation pipeline](crate::evaluate) as the registered ones.
//!
//! # Protocol
//! - **Input**: the instance as a `.grid` file (`#` pixel, `.` empty, first line the top row;
//!   `; key: value` comment lines may precede it). Its path replaces `{instance}` in the
//!   command.
//! - **Output**: the walk(s) as tour JSON, `{"cycles": [[[x, y], ...], ...]}` (pixel
//!   `[x, y]` names a pixel: x is its column in the .grid from 0, y its row counted from the
//!   last line up, from 0 — as `mowmill solve --tour-out` writes them; consecutive pixels of a
//!   walk share a side, and the walk closes from its last pixel back to its first), to the path that replaces
//!   `{tour_out}`. A tour objective needs exactly one cycle.
//! - **Objective**: `{objective}` is replaced by the objective asked for; when the command
//!   contains it, the program runs once per objective, otherwise once, and its walk is judged
//!   under every declared objective.
//! - **Environment**: `MOWMILL_INSTANCE`, `MOWMILL_TOUR_OUT`, `MOWMILL_OBJECTIVE` (empty
//!   when run once for all), `MOWMILL_TIME_LIMIT` (seconds), `MOWMILL_N` (pixels).
//! - **Working directory**: the folder of the config that declares it (the current folder for
//!   `solve --command`).
//! - **Exit code**: 0 means the tour file is written; anything else is an error row with the
//!   last lines of the program's stderr. A run longer than `time_limit` seconds is killed
//!   (with its process group) and becomes an error row. A missing, oversized or malformed
//!   tour file, or one that is not a regular file, is an error row; a walk the checker
//!   rejects is a row with `valid = false`.
//! - **Confinement**: a private scratch folder per run, a memory limit
//!   (`memory_limit`, RLIMIT_AS), stdout and stderr drained and capped, and the program's
//!   process group (and every process carrying its `MOWMILL_RUN` token) killed on every way
//!   out of a run and when mowmill is killed: see the `confine` module and docs/outside.md.

use crate::algorithms::theorems::{Bound, Measure, Paper, Realized, Theorem};
use crate::algorithms::{Against, Guarantee, Objective, Output, Quantity, Solution, When};
use crate::error::{Error, Result};
use crate::gridfile::GridFile;
use crate::region::Region;
use crate::tour::CycleCover;
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// The `[[algorithm]]` table of a config, as written.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct OutsideSpec {
    pub name: String,
    /// Program and arguments; `{instance}`, `{tour_out}` and `{objective}` are filled in.
    pub command: Vec<String>,
    /// Objectives its walks are judged under: length, turns, cc-turns, lawn-length.
    pub objectives: Vec<String>,
    /// An optional claim to check: `{ objective = "turns", factor = "7/2", against = "opt" }`.
    #[serde(default)]
    pub guarantee: Option<GuaranteeSpec>,
    /// Seconds before the program is killed.
    #[serde(default = "default_time_limit")]
    pub time_limit: f64,
    /// Address-space limit of the program (RLIMIT_AS, each of its processes): bytes or a size
    /// such as "512 MiB", "4G", or "unlimited". Default [`DEFAULT_MEMORY_LIMIT`].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub memory_limit: Option<MemoryLimit>,
}

/// A claim `objective ≤ factor · against` of an outside algorithm.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct GuaranteeSpec {
    pub objective: String,
    /// A rational number: "7/2", "3" or "1.25".
    pub factor: String,
    /// `opt` (the objective's optimum) or `n` (the number of pixels).
    #[serde(default = "default_against")]
    pub against: String,
}

fn default_time_limit() -> f64 {
    60.0
}

fn default_against() -> String {
    "opt".into()
}

/// An outside algorithm ready to run.
#[derive(Clone, Debug)]
pub struct OutsideAlgorithm {
    pub name: String,
    pub command: Vec<String>,
    pub objectives: Vec<Objective>,
    pub guarantees: Vec<Guarantee>,
    pub time_limit: f64,
    /// Address-space limit in bytes (`None`: unlimited).
    pub memory_limit: Option<u64>,
    /// The folder the program runs in.
    pub dir: PathBuf,
}

impl OutsideAlgorithm {
    /// Checks a spec (names, objectives, the claim, the time limit); `dir` is the folder
    /// relative paths of the command are resolved in. Errors say which key is wrong.
    pub fn from_spec(spec: &OutsideSpec, dir: &Path) -> std::result::Result<Self, String> {
        if spec.name.is_empty() || spec.name.contains(['[', ']', ',', '/']) {
            return Err(format!(
                "name {:?}: expected a non-empty name without [ ] , /",
                spec.name
            ));
        }
        if crate::algorithms::find(&spec.name).is_some() || spec.name == "exact" {
            return Err(format!(
                "name {:?} is a registered algorithm: choose another",
                spec.name
            ));
        }
        if spec.command.is_empty() {
            return Err("command: expected [\"program\", \"arg\", ...]".into());
        }
        if !spec.command.iter().any(|a| a.contains("{tour_out}")) {
            return Err(
                "command: must contain {tour_out} (where the program writes its walk)".into(),
            );
        }
        if !(spec.time_limit.is_finite() && spec.time_limit > 0.0) {
            return Err("time_limit: expected a positive number of seconds".into());
        }
        let memory_limit = match &spec.memory_limit {
            None => Some(DEFAULT_MEMORY_LIMIT),
            Some(m) => m.bytes().map_err(|e| format!("memory_limit: {e}"))?,
        };
        let objectives: Vec<Objective> = spec
            .objectives
            .iter()
            .map(|o| match o.parse::<Objective>() {
                Ok(Objective::LawnTsp) => Err(format!(
                    "{o:?} is the exact solver's reference, not an output: expected one of {}",
                    Objective::NAMES.join(", ")
                )),
                other => other,
            })
            .collect::<std::result::Result<_, _>>()
            .map_err(|e| format!("objectives: {e}"))?;
        if objectives.is_empty() {
            return Err("objectives: expected at least one".into());
        }
        let mut guarantees = Vec::new();
        if let Some(g) = &spec.guarantee {
            let objective: Objective = g
                .objective
                .parse()
                .map_err(|e| format!("guarantee.objective: {e}"))?;
            if !objectives.contains(&objective) {
                return Err(format!(
                    "guarantee.objective: {objective} is not one of the declared objectives"
                ));
            }
            let (num, den) =
                parse_factor(&g.factor).map_err(|e| format!("guarantee.factor: {e}"))?;
            let against = match g.against.as_str() {
                "opt" => Against::Opt,
                "n" => Against::N,
                other => {
                    return Err(format!(
                        "guarantee.against: expected opt or n, got {other:?}"
                    ));
                }
            };
            // Leaked once per declared algorithm: guarantees carry 'static texts and theorems.
            let leak = |s: String| -> &'static str { Box::leak(s.into_boxed_str()) };
            let source = leak(format!("claimed in the config of {}", spec.name));
            let theorem: &'static Theorem = Box::leak(Box::new(Theorem {
                paper: Paper::Outside,
                id: leak(format!("claim of {}", spec.name)),
                statement: leak(format!("{objective} <= {} {}", g.factor, g.against)),
                factor: leak(g.factor.clone()),
                measure: Measure::Bound(Bound::new(Quantity::Value, num, den, 0, against)),
                when: When::Always,
                realized: Realized::ByAlgorithms,
                tight: None,
            }));
            guarantees.push(Guarantee::of_theorem(
                objective,
                When::Always,
                theorem,
                source,
            ));
        }
        Ok(OutsideAlgorithm {
            name: spec.name.clone(),
            command: spec.command.clone(),
            objectives,
            guarantees,
            time_limit: spec.time_limit,
            memory_limit,
            dir: dir.to_path_buf(),
        })
    }

    /// Runs the program on `instance` for `objectives` and reads its walks back.
    pub fn run<T: OutsideTarget>(
        &self,
        instance: &T,
        objectives: &[Objective],
    ) -> Result<Solution<T::Cover>> {
        let work = scratch_dir(&self.name)?;
        let (name, text) = instance.instance_file()?;
        let file = work.path().join(name);
        write_new(&file, &text)?;
        let per_objective = self.command.iter().any(|a| a.contains("{objective}"));
        let mut solution = Solution::default();
        if per_objective {
            for &objective in objectives {
                let cover = self.run_once(instance, work.path(), &file, Some(objective))?;
                solution.outputs.push(Output { objective, cover });
            }
        } else {
            let cover = self.run_once(instance, work.path(), &file, None)?;
            for &objective in objectives {
                solution.outputs.push(Output {
                    objective,
                    cover: cover.clone(),
                });
            }
        }
        Ok(solution)
    }

    fn run_once<T: OutsideTarget>(
        &self,
        target: &T,
        work: &Path,
        instance: &Path,
        objective: Option<Objective>,
    ) -> Result<T::Cover> {
        let tag = objective.map_or("all".to_string(), |o| o.to_string());
        let tour_out = work.join(format!("tour-{tag}.json"));
        let fill = |a: &str| {
            a.replace("{instance}", &instance.display().to_string())
                .replace("{tour_out}", &tour_out.display().to_string())
                .replace("{objective}", objective.map_or("", |o| o.name()))
        };
        let args: Vec<String> = self.command.iter().map(|a| fill(a)).collect();
        let mut cmd = Command::new(&args[0]);
        cmd.args(&args[1..])
            .current_dir(&self.dir)
            .stdin(Stdio::null())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .env("MOWMILL_INSTANCE", instance)
            .env("MOWMILL_TOUR_OUT", &tour_out)
            .env("MOWMILL_OBJECTIVE", objective.map_or("", |o| o.name()))
            .env("MOWMILL_TIME_LIMIT", self.time_limit.to_string())
            .env("MOWMILL_N", target.size().to_string());
        let token = confine::prepare(&mut cmd, self.memory_limit);
        let child = cmd.spawn().map_err(|e| {
            let memory = match self.memory_limit {
                Some(m) if e.raw_os_error() == Some(libc::ENOMEM) => {
                    format!(" (memory_limit {})", show_bytes(m))
                }
                _ => String::new(),
            };
            Error::solver(format!(
                "{}: cannot start {:?} (in {}): {e}{memory}",
                self.name,
                args[0],
                self.dir.display()
            ))
        })?;
        // From here on, every way out of this function (return, `?`, panic) kills the
        // program's process group and every process that carries its token.
        let mut group = confine::Group::new(child, token);
        let stdout = group.child.stdout.take().map(Drain::start);
        let stderr = group.child.stderr.take().map(Drain::start);
        let start = Instant::now();
        let limit = Duration::from_secs_f64(self.time_limit);
        loop {
            match group.exited() {
                Ok(true) => break,
                Ok(false) if start.elapsed() > limit => {
                    let _ = group.finish();
                    return Err(Error::solver(format!(
                        "{}: time limit of {} s exceeded; killed",
                        self.name, self.time_limit
                    )));
                }
                Ok(false) => std::thread::sleep(Duration::from_millis(5)),
                Err(e) => return Err(Error::solver(format!("{}: {e}", self.name))),
            }
        }
        let status = group
            .finish()
            .map_err(|e| Error::solver(format!("{}: {e}", self.name)))?;
        // The group is dead: the pipes close unless a process escaped both the group and the
        // token (then what was read so far is used and the reader ends when the pipe closes).
        let stdout = stdout.map(|d| d.finish()).unwrap_or_default();
        let stderr = stderr.map(|d| d.finish()).unwrap_or_default();
        if !status.success() {
            return Err(Error::solver(format!(
                "{}: {}{}{}",
                self.name,
                failure(status, &stderr, self.memory_limit),
                stderr.note("stderr"),
                if stderr.total == 0 {
                    stdout.note("stdout")
                } else {
                    String::new()
                }
            )));
        }
        read_tour(&tour_out, tour_bound(target.size()))
            .and_then(|text| {
                target
                    .parse_tour(&text, &tour_out.display().to_string())
                    .map_err(|e| format!("malformed tour: {e}"))
            })
            .map_err(|e| {
                Error::invalid_output(format!("{}: {e}{}", self.name, stderr.note("stderr")))
            })
    }
}

/// An instance an outside program can solve: the file it is given, and how the tour file it
/// writes reads back. Grid regions are given as `.grid` files (shifted into the quadrant, the
/// walks shifted back) and answer with the tour JSON of `validate`; discrete instances are
/// given as `.dm` files and answer with discrete tour JSON (`{"cycles": [[0, 1, ...]]}`).
pub trait OutsideTarget {
    /// The walks the program returns.
    type Cover: Clone;
    /// The name of the instance file in the program's scratch folder, and its text.
    fn instance_file(&self) -> Result<(&'static str, String)>;
    /// The walks in the tour file's `text` (`name` for messages), in this instance's terms.
    fn parse_tour(&self, text: &str, name: &str) -> Result<Self::Cover>;
    /// The number of pixels or vertices (`MOWMILL_N`; the tour file's size limit grows with
    /// it).
    fn size(&self) -> usize;
}

/// The shift that moves `region` into the quadrant of non-negative coordinates (the `.grid`
/// format has none below 0).
fn quadrant_shift(region: &Region) -> (i32, i32) {
    let b = region.bbox();
    ((-b.min_x).max(0), (-b.min_y).max(0))
}

impl OutsideTarget for Region {
    type Cover = CycleCover;

    fn instance_file(&self) -> Result<(&'static str, String)> {
        let (dx, dy) = quadrant_shift(self);
        let shifted = self.translated(dx, dy)?;
        Ok((
            "instance.grid",
            GridFile::with_meta(shifted, &[]).to_text()?,
        ))
    }

    fn parse_tour(&self, text: &str, name: &str) -> Result<CycleCover> {
        let (dx, dy) = quadrant_shift(self);
        Ok(shift(CycleCover::from_json(text, name)?, -dx, -dy))
    }

    fn size(&self) -> usize {
        self.len()
    }
}

impl OutsideTarget for crate::discrete::Discrete {
    type Cover = crate::discrete::format::DiscreteCover;

    fn instance_file(&self) -> Result<(&'static str, String)> {
        Ok(("instance.dm", crate::discrete::format::to_text(self)))
    }

    fn parse_tour(&self, text: &str, name: &str) -> Result<Self::Cover> {
        crate::discrete::format::DiscreteCover::from_json(text, name)
    }

    fn size(&self) -> usize {
        self.len()
    }
}

fn shift(mut cover: CycleCover, dx: i32, dy: i32) -> CycleCover {
    for walk in &mut cover.cycles {
        for p in walk {
            *p = crate::region::Pixel::new(p.x + dx, p.y + dy);
        }
    }
    cover
}

/// "7/2", "3" or "1.25" as a fraction num/den.
fn parse_factor(s: &str) -> std::result::Result<(i64, i64), String> {
    let bad = || format!("expected a positive rational like \"7/2\", \"3\" or \"1.25\", got {s:?}");
    let (num, den) = if let Some((a, b)) = s.split_once('/') {
        (
            a.trim().parse::<i64>().map_err(|_| bad())?,
            b.trim().parse::<i64>().map_err(|_| bad())?,
        )
    } else if let Some((a, b)) = s.split_once('.') {
        if b.len() > 9 || !b.chars().all(|c| c.is_ascii_digit()) {
            return Err(bad());
        }
        let den = 10i64.pow(b.len() as u32);
        let whole = a.trim().parse::<i64>().map_err(|_| bad())?;
        let frac = if b.is_empty() {
            0
        } else {
            b.parse::<i64>().map_err(|_| bad())?
        };
        (whole * den + frac, den)
    } else {
        (s.trim().parse::<i64>().map_err(|_| bad())?, 1)
    };
    if num <= 0 || den <= 0 {
        return Err(bad());
    }
    Ok((num, den))
}

/// The largest tour file read back (bytes), whatever the instance: a walk of a region within
/// the pixel limit at the lengths the papers' algorithms reach needs a small fraction of it.
pub const MAX_TOUR_BYTES: u64 = 256 << 20;

/// The largest tour file read back for an instance of `n` pixels: 1 MiB plus 1 KiB per pixel
/// (about fifty `[x, y]` pairs per pixel, pretty-printed), at most [`MAX_TOUR_BYTES`].
pub fn tour_bound(n: usize) -> u64 {
    ((1u64 << 20) + 1024 * n as u64).min(MAX_TOUR_BYTES)
}

/// The default address-space limit of an outside program (`memory_limit`): 4 GiB.
pub const DEFAULT_MEMORY_LIMIT: u64 = 4 << 30;

/// Bytes kept of a program's stdout and of its stderr: the first and the last this many.
pub const CAPTURE_KEEP: usize = 64 << 10;

/// A `memory_limit` as written: a number of bytes or a size such as "512 MiB", "4G",
/// "unlimited".
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(untagged)]
pub enum MemoryLimit {
    Bytes(i64),
    Text(String),
}

impl MemoryLimit {
    /// The limit in bytes; `None` for unlimited.
    pub fn bytes(&self) -> std::result::Result<Option<u64>, String> {
        match self {
            MemoryLimit::Bytes(b) if *b >= 1 << 20 => Ok(Some(*b as u64)),
            MemoryLimit::Bytes(b) => Err(format!(
                "{b} bytes: expected at least 1 MiB (a number of bytes, a size such as \"4 GiB\", or \"unlimited\")"
            )),
            MemoryLimit::Text(t) => parse_memory_limit(t),
        }
    }
}

/// "4 GiB", "512M", "1.5g", "1073741824", "unlimited" as bytes (`None`: no limit). Units
/// are binary (K = KiB = 1024 bytes, M = MiB, G = GiB, T = TiB); at least 1 MiB.
pub fn parse_memory_limit(s: &str) -> std::result::Result<Option<u64>, String> {
    let bad = || {
        format!(
            "{s:?}: expected a size such as \"4 GiB\", \"512M\" or a number of bytes (at least 1 MiB), or \"unlimited\""
        )
    };
    let t = s.trim();
    if t.eq_ignore_ascii_case("unlimited") || t.eq_ignore_ascii_case("none") {
        return Ok(None);
    }
    let split = t
        .find(|c: char| !(c.is_ascii_digit() || c == '.'))
        .unwrap_or(t.len());
    let (number, unit) = t.split_at(split);
    let unit_bytes: u64 = match unit.trim().to_ascii_lowercase().as_str() {
        "" | "b" => 1,
        "k" | "kb" | "kib" => 1 << 10,
        "m" | "mb" | "mib" => 1 << 20,
        "g" | "gb" | "gib" => 1 << 30,
        "t" | "tb" | "tib" => 1 << 40,
        _ => return Err(bad()),
    };
    let value: f64 = number.parse().map_err(|_| bad())?;
    let bytes = value * unit_bytes as f64;
    if !(bytes.is_finite() && bytes >= (1u64 << 20) as f64 && bytes < u64::MAX as f64) {
        return Err(bad());
    }
    Ok(Some(bytes.round() as u64))
}

/// "4 GiB", "64 MiB" or "1234567 bytes".
fn show_bytes(b: u64) -> String {
    for (unit, name) in [(1u64 << 40, "TiB"), (1 << 30, "GiB"), (1 << 20, "MiB")] {
        if b.is_multiple_of(unit) {
            return format!("{} {name}", b / unit);
        }
    }
    format!("{b} bytes")
}

/// Why a program failed, from its exit status and stderr: out of memory when its stderr
/// says so (a memory limit was set), possibly out of memory when it died of a signal an
/// allocation failure raises.
fn failure(
    status: std::process::ExitStatus,
    stderr: &Capture,
    memory_limit: Option<u64>,
) -> String {
    let Some(limit) = memory_limit else {
        return format!("exited with {status}");
    };
    let said = String::from_utf8_lossy(&stderr.last(8192)).to_ascii_lowercase();
    let words = [
        "out of memory",
        "outofmemory",
        "memoryerror",
        "cannot allocate memory",
        "bad_alloc",
        "memory allocation",
        "failed to allocate",
        "allocation failed",
    ];
    if words.iter().any(|w| said.contains(w)) {
        return format!(
            "out of memory (memory_limit {}): exited with {status}",
            show_bytes(limit)
        );
    }
    #[cfg(unix)]
    {
        use std::os::unix::process::ExitStatusExt;
        if let Some(sig) = status.signal()
            && [libc::SIGSEGV, libc::SIGABRT, libc::SIGBUS, libc::SIGKILL].contains(&sig)
        {
            return format!(
                "exited with {status}: possibly out of memory (memory_limit {})",
                show_bytes(limit)
            );
        }
    }
    format!("exited with {status}")
}

/// Reads the text of the tour file at `path`: only a regular file (never a link, FIFO, device
/// or folder, which could block or never end), at most `bound` bytes, UTF-8.
fn read_tour(path: &Path, bound: u64) -> std::result::Result<String, String> {
    use std::io::Read;
    let meta = std::fs::symlink_metadata(path)
        .map_err(|_| "exited 0 but wrote no tour file ({tour_out})".to_string())?;
    let not_regular = |t: std::fs::FileType| {
        format!(
            "{{tour_out}} is {}, not a regular file: not read",
            file_kind(t)
        )
    };
    if !meta.file_type().is_file() {
        return Err(not_regular(meta.file_type()));
    }
    let mut options = std::fs::OpenOptions::new();
    options.read(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        // The file may have been swapped since the check: never follow a link, never wait
        // for a FIFO's writer; fstat decides.
        options.custom_flags(libc::O_NOFOLLOW | libc::O_NONBLOCK);
    }
    let file = options
        .open(path)
        .map_err(|e| format!("cannot open the tour file ({{tour_out}}): {e}"))?;
    let meta = file
        .metadata()
        .map_err(|e| format!("cannot stat the tour file ({{tour_out}}): {e}"))?;
    if !meta.file_type().is_file() {
        return Err(not_regular(meta.file_type()));
    }
    let too_big = |size: u64| {
        format!("tour file of {size} bytes is above the limit of {bound} bytes for this instance")
    };
    if meta.len() > bound {
        return Err(too_big(meta.len()));
    }
    let mut bytes = Vec::with_capacity(meta.len() as usize);
    file.take(bound + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| format!("cannot read the tour file ({{tour_out}}): {e}"))?;
    if bytes.len() as u64 > bound {
        return Err(too_big(bytes.len() as u64));
    }
    String::from_utf8(bytes).map_err(|e| format!("malformed tour: not UTF-8: {e}"))
}

fn file_kind(t: std::fs::FileType) -> &'static str {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if t.is_fifo() {
            return "a FIFO";
        }
        if t.is_socket() {
            return "a socket";
        }
        if t.is_block_device() || t.is_char_device() {
            return "a device";
        }
    }
    if t.is_symlink() {
        "a symbolic link"
    } else if t.is_dir() {
        "a folder"
    } else {
        "not a regular file"
    }
}

/// The first and the last [`CAPTURE_KEEP`] bytes of a stream, and its length.
#[derive(Default, Debug)]
struct Capture {
    head: Vec<u8>,
    tail: std::collections::VecDeque<u8>,
    total: u64,
}

impl Capture {
    fn push(&mut self, mut bytes: &[u8]) {
        self.total += bytes.len() as u64;
        let take = (CAPTURE_KEEP - self.head.len()).min(bytes.len());
        self.head.extend_from_slice(&bytes[..take]);
        bytes = &bytes[take..];
        if bytes.len() >= CAPTURE_KEEP {
            self.tail.clear();
            bytes = &bytes[bytes.len() - CAPTURE_KEEP..];
        }
        self.tail.extend(bytes);
        let excess = self.tail.len().saturating_sub(CAPTURE_KEEP);
        self.tail.drain(..excess);
    }

    /// Bytes received but not kept.
    fn dropped(&self) -> u64 {
        self.total - (self.head.len() + self.tail.len()) as u64
    }

    /// The last `n` kept bytes.
    fn last(&self, n: usize) -> Vec<u8> {
        let kept: Vec<u8> = self.head.iter().chain(self.tail.iter()).copied().collect();
        kept[kept.len().saturating_sub(n)..].to_vec()
    }

    /// "; stderr: last lines" for an error message, with the size when some was dropped.
    fn note(&self, stream: &str) -> String {
        let tail = self.last(600);
        let tail = String::from_utf8_lossy(&tail);
        let tail = tail.trim();
        if tail.is_empty() {
            return String::new();
        }
        let size = if self.dropped() > 0 {
            format!(
                " ({} bytes, only the first and last {} KiB kept)",
                self.total,
                CAPTURE_KEEP >> 10
            )
        } else {
            String::new()
        };
        format!("; {stream}{size}: {}", tail.replace('\n', " | "))
    }
}

/// A thread reading a pipe to its end into a [`Capture`], so the program never blocks on a
/// full pipe and never fills memory or disk.
struct Drain {
    capture: std::sync::Arc<std::sync::Mutex<Capture>>,
    done: std::sync::mpsc::Receiver<()>,
}

impl Drain {
    fn start(mut pipe: impl std::io::Read + Send + 'static) -> Drain {
        let capture = std::sync::Arc::new(std::sync::Mutex::new(Capture::default()));
        let (tx, done) = std::sync::mpsc::channel();
        let shared = capture.clone();
        std::thread::spawn(move || {
            let mut buf = vec![0u8; 64 << 10];
            loop {
                match pipe.read(&mut buf) {
                    Ok(0) => break,
                    Ok(k) => {
                        if let Ok(mut c) = shared.lock() {
                            c.push(&buf[..k]);
                        }
                    }
                    Err(e) if e.kind() == std::io::ErrorKind::Interrupted => {}
                    Err(_) => break,
                }
            }
            let _ = tx.send(());
        });
        Drain { capture, done }
    }

    /// What was read, once the pipe closed or after a grace of 0.2 s (a process that escaped
    /// the kill may hold it open).
    fn finish(self) -> Capture {
        let _ = self.done.recv_timeout(Duration::from_millis(200));
        match self.capture.lock() {
            Ok(mut c) => std::mem::take(&mut *c),
            Err(_) => Capture::default(),
        }
    }
}

/// A private scratch folder (a fresh random name, mode 0700, created atomically), removed
/// on drop; its files are created with `create_new`, so nothing planted is followed.
fn scratch_dir(tag: &str) -> Result<tempfile::TempDir> {
    let safe: String = tag
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect();
    let prefix = format!("mowmill-{safe}-");
    let mut builder = tempfile::Builder::new();
    builder.prefix(&prefix);
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        builder.permissions(std::fs::Permissions::from_mode(0o700));
    }
    builder
        .tempdir()
        .map_err(|e| Error::io(&std::env::temp_dir(), e))
}

/// Writes a new file (never an existing path or a link).
fn write_new(path: &Path, text: &str) -> Result<()> {
    use std::io::Write;
    let mut options = std::fs::OpenOptions::new();
    options.write(true).create_new(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        options.mode(0o600).custom_flags(libc::O_NOFOLLOW);
    }
    let mut f = options.open(path).map_err(|e| Error::io(path, e))?;
    f.write_all(text.as_bytes()).map_err(|e| Error::io(path, e))
}

/// Confinement of outside programs: each runs in its own process group with a memory limit,
/// and dies with mowmill.
///
/// - Each program leads a new process group; every way out of a run (success, failure, time
///   limit, error) kills the group with SIGKILL while the leader is still unreaped (so its id
///   cannot be reused), then every process whose environment carries the run's token
///   (`MOWMILL_RUN=<mowmill pid>-<k>`, Linux: read from `/proc/*/environ`), which catches
///   descendants that left the group with `setsid` or `setpgid`.
/// - SIGINT, SIGTERM and SIGHUP of mowmill (unless ignored when it started) kill the live
///   groups in the handler, then a thread kills every process with a token of this mowmill
///   and the signal is raised again with its default action.
/// - On Linux the program gets PR_SET_PDEATHSIG = SIGKILL, so even a SIGKILL of mowmill kills
///   it; its own children are not reached then (nothing of mowmill runs after a SIGKILL).
/// - `memory_limit` is RLIMIT_AS (address space) of the program, inherited by its children
///   (each has its own).
///
/// A descendant that both leaves the group and clears its environment (`env -i`) escapes.
#[cfg(unix)]
mod confine {
    use std::io;
    use std::os::unix::process::CommandExt;
    use std::process::{Child, Command, ExitStatus};
    use std::sync::atomic::{AtomicBool, AtomicI32, AtomicU64, Ordering};

    /// The environment variable that marks every process of one run.
    pub const RUN_ENV: &str = "MOWMILL_RUN";

    /// Process groups of running programs (0: a free slot), read by the signal handler.
    static LIVE: [AtomicI32; 1024] = [const { AtomicI32::new(0) }; 1024];
    /// The write end of the pipe that wakes the cleanup thread (-1: none).
    static WAKE: AtomicI32 = AtomicI32::new(-1);
    static SIGNALLED: AtomicBool = AtomicBool::new(false);

    /// Sets up `cmd` (own process group, death signal, memory limit, token) and returns the
    /// run's token.
    pub fn prepare(cmd: &mut Command, memory_limit: Option<u64>) -> String {
        static RUNS: AtomicU64 = AtomicU64::new(0);
        install_handlers();
        let token = format!(
            "{}-{}",
            std::process::id(),
            RUNS.fetch_add(1, Ordering::Relaxed)
        );
        cmd.env(RUN_ENV, &token).process_group(0);
        let parent = std::process::id() as libc::pid_t;
        // SAFETY: between fork and exec only async-signal-safe calls (prctl, getppid,
        // getrlimit, setrlimit), no allocation.
        unsafe {
            cmd.pre_exec(move || {
                #[cfg(target_os = "linux")]
                {
                    if libc::prctl(libc::PR_SET_PDEATHSIG, libc::SIGKILL) == -1 {
                        return Err(io::Error::last_os_error());
                    }
                    // mowmill died before the death signal was set.
                    if libc::getppid() != parent {
                        return Err(io::Error::from_raw_os_error(libc::ESRCH));
                    }
                }
                #[cfg(not(target_os = "linux"))]
                let _ = parent;
                if let Some(limit) = memory_limit {
                    let mut old = libc::rlimit {
                        rlim_cur: 0,
                        rlim_max: 0,
                    };
                    if libc::getrlimit(libc::RLIMIT_AS, &mut old) == -1 {
                        return Err(io::Error::last_os_error());
                    }
                    let limit = (limit as libc::rlim_t).min(old.rlim_max);
                    let new = libc::rlimit {
                        rlim_cur: limit,
                        rlim_max: limit,
                    };
                    if libc::setrlimit(libc::RLIMIT_AS, &new) == -1 {
                        return Err(io::Error::last_os_error());
                    }
                }
                Ok(())
            });
        }
        token
    }

    /// A running program and its process group, killed on drop.
    pub struct Group {
        pub child: Child,
        token: String,
        slot: Option<usize>,
        status: Option<ExitStatus>,
    }

    impl Group {
        pub fn new(child: Child, token: String) -> Group {
            let pgid = child.id() as i32;
            let slot = LIVE.iter().position(|s| {
                s.compare_exchange(0, pgid, Ordering::SeqCst, Ordering::SeqCst)
                    .is_ok()
            });
            Group {
                child,
                token,
                slot,
                status: None,
            }
        }

        /// Whether the program exited, without reaping it (its id stays reserved for the
        /// group kill).
        pub fn exited(&mut self) -> io::Result<bool> {
            // SAFETY: a zeroed siginfo_t is valid; waitid writes it.
            let mut info: libc::siginfo_t = unsafe { std::mem::zeroed() };
            let flags = libc::WEXITED | libc::WNOHANG | libc::WNOWAIT;
            // SAFETY: plain syscall on our own child.
            let r = unsafe {
                libc::waitid(libc::P_PID, self.child.id() as libc::id_t, &mut info, flags)
            };
            if r == -1 {
                let e = io::Error::last_os_error();
                return if e.kind() == io::ErrorKind::Interrupted {
                    Ok(false)
                } else {
                    Err(e)
                };
            }
            // SAFETY: waitid filled in the pid (0 when no child changed state).
            Ok(unsafe { info.si_pid() } != 0)
        }

        /// Kills the group and every process with the run's token, then reaps the program.
        pub fn finish(&mut self) -> io::Result<ExitStatus> {
            if let Some(s) = self.status {
                return Ok(s);
            }
            // SAFETY: kill(2) on the group the unreaped child leads.
            unsafe {
                libc::kill(-(self.child.id() as i32), libc::SIGKILL);
            }
            kill_tagged(&format!("{RUN_ENV}={}", self.token), false);
            let status = self.child.wait();
            if let Some(slot) = self.slot.take() {
                LIVE[slot].store(0, Ordering::SeqCst);
            }
            let status = status?;
            self.status = Some(status);
            Ok(status)
        }
    }

    impl Drop for Group {
        fn drop(&mut self) {
            let _ = self.finish();
        }
    }

    /// SIGKILLs every other process whose environment has the entry `entry` (or an entry
    /// starting with it), until a scan finds no new one (Linux; elsewhere nothing).
    fn kill_tagged(entry: &str, prefix: bool) {
        #[cfg(target_os = "linux")]
        {
            let me = std::process::id() as i32;
            let mut killed = std::collections::HashSet::new();
            for _ in 0..20 {
                let Ok(dir) = std::fs::read_dir("/proc") else {
                    return;
                };
                let mut new = 0;
                for e in dir.flatten() {
                    let Some(pid) = e.file_name().to_str().and_then(|s| s.parse::<i32>().ok())
                    else {
                        continue;
                    };
                    if pid == me || killed.contains(&pid) {
                        continue;
                    }
                    let Ok(env) = std::fs::read(format!("/proc/{pid}/environ")) else {
                        continue;
                    };
                    let hit = env.split(|&b| b == 0).any(|v| {
                        if prefix {
                            v.starts_with(entry.as_bytes())
                        } else {
                            v == entry.as_bytes()
                        }
                    });
                    if hit {
                        // SAFETY: kill(2) of a process of this run.
                        unsafe {
                            libc::kill(pid, libc::SIGKILL);
                        }
                        killed.insert(pid);
                        new += 1;
                    }
                }
                if new == 0 {
                    return;
                }
            }
        }
        #[cfg(not(target_os = "linux"))]
        let _ = (entry, prefix);
    }

    fn install_handlers() {
        static ONCE: std::sync::Once = std::sync::Once::new();
        ONCE.call_once(|| {
            let mut fds = [0 as libc::c_int; 2];
            // SAFETY: pipe(2) into a local array; fcntl on the new descriptors.
            unsafe {
                if libc::pipe(fds.as_mut_ptr()) == -1 {
                    return;
                }
                for fd in fds {
                    libc::fcntl(fd, libc::F_SETFD, libc::FD_CLOEXEC);
                }
            }
            let read_end = fds[0];
            if std::thread::Builder::new()
                .name("mowmill-outside-cleanup".into())
                .spawn(move || cleanup_on_signal(read_end))
                .is_err()
            {
                return;
            }
            WAKE.store(fds[1], Ordering::SeqCst);
            for sig in [libc::SIGINT, libc::SIGTERM, libc::SIGHUP] {
                // SAFETY: sigaction with a handler that only calls async-signal-safe
                // functions; a signal ignored at start stays ignored.
                unsafe {
                    let mut old: libc::sigaction = std::mem::zeroed();
                    if libc::sigaction(sig, std::ptr::null(), &mut old) == -1
                        || old.sa_sigaction == libc::SIG_IGN
                    {
                        continue;
                    }
                    let mut new: libc::sigaction = std::mem::zeroed();
                    new.sa_sigaction = on_signal as *const () as libc::sighandler_t;
                    new.sa_flags = libc::SA_RESTART;
                    libc::sigemptyset(&mut new.sa_mask);
                    libc::sigaction(sig, &new, std::ptr::null_mut());
                }
            }
        });
    }

    extern "C" fn on_signal(sig: libc::c_int) {
        for slot in &LIVE {
            let pgid = slot.load(Ordering::SeqCst);
            if pgid > 0 {
                // SAFETY: kill(2) is async-signal-safe.
                unsafe {
                    libc::kill(-pgid, libc::SIGKILL);
                }
            }
        }
        let fd = WAKE.load(Ordering::SeqCst);
        if fd < 0 || SIGNALLED.swap(true, Ordering::SeqCst) {
            // A second signal (or no cleanup thread): die now.
            // SAFETY: signal and raise are async-signal-safe.
            unsafe {
                libc::signal(sig, libc::SIG_DFL);
                libc::raise(sig);
            }
            return;
        }
        let byte = sig as u8;
        // SAFETY: write(2) of one byte from the stack is async-signal-safe.
        unsafe {
            libc::write(fd, &byte as *const u8 as *const libc::c_void, 1);
        }
    }

    fn cleanup_on_signal(fd: libc::c_int) {
        let mut byte = 0u8;
        loop {
            // SAFETY: read(2) of one byte into a local.
            let r = unsafe { libc::read(fd, &mut byte as *mut u8 as *mut libc::c_void, 1) };
            if r == 1 {
                break;
            }
            if r == -1 && io::Error::last_os_error().kind() == io::ErrorKind::Interrupted {
                continue;
            }
            return;
        }
        kill_tagged(&format!("{RUN_ENV}={}-", std::process::id()), true);
        let sig = byte as libc::c_int;
        // SAFETY: restore the default action and raise the signal again: mowmill ends as the
        // signal asked.
        unsafe {
            libc::signal(sig, libc::SIG_DFL);
            libc::raise(sig);
            libc::_exit(128 + sig);
        }
    }
}

/// Elsewhere: no process group kill beyond the program itself, no memory limit.
#[cfg(not(unix))]
mod confine {
    use std::process::{Child, Command, ExitStatus};

    pub fn prepare(_cmd: &mut Command, _memory_limit: Option<u64>) -> String {
        String::new()
    }

    pub struct Group {
        pub child: Child,
        status: Option<ExitStatus>,
    }

    impl Group {
        pub fn new(child: Child, _token: String) -> Group {
            Group {
                child,
                status: None,
            }
        }

        pub fn exited(&mut self) -> std::io::Result<bool> {
            Ok(self.child.try_wait()?.is_some())
        }

        pub fn finish(&mut self) -> std::io::Result<ExitStatus> {
            if let Some(s) = self.status {
                return Ok(s);
            }
            let _ = self.child.kill();
            let s = self.child.wait()?;
            self.status = Some(s);
            Ok(s)
        }
    }

    impl Drop for Group {
        fn drop(&mut self) {
            let _ = self.finish();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Captured output is capped: a stream of any length keeps its first and last
    /// CAPTURE_KEEP bytes and counts the rest (it was kept whole).
    #[test]
    fn a_capture_keeps_the_ends_of_a_flood() {
        let mut c = Capture::default();
        let chunk = vec![b'x'; 1 << 20];
        for _ in 0..50 {
            c.push(&chunk);
        }
        c.push(b"the end");
        assert_eq!(c.total, 50 * (1 << 20) + 7);
        assert_eq!(c.head.len() + c.tail.len(), 2 * CAPTURE_KEEP);
        assert_eq!(c.last(7), b"the end");
        assert_eq!(c.dropped(), c.total - 2 * CAPTURE_KEEP as u64);
        let mut small = Capture::default();
        small.push(b"a\nb");
        assert_eq!(
            (small.dropped(), small.note("stderr")),
            (0, "; stderr: a | b".into())
        );
    }

    /// Memory limits as written in a config or on the command line.
    #[test]
    fn memory_limits_read_as_bytes() {
        assert_eq!(parse_memory_limit("4 GiB"), Ok(Some(4 << 30)));
        assert_eq!(parse_memory_limit("512M"), Ok(Some(512 << 20)));
        assert_eq!(parse_memory_limit("1.5g"), Ok(Some(3 << 29)));
        assert_eq!(parse_memory_limit("unlimited"), Ok(None));
        assert_eq!(MemoryLimit::Bytes(1 << 30).bytes(), Ok(Some(1 << 30)));
        for bad in ["", "lots", "-1G", "0", "100", "4 GB extra", "1e99T"] {
            assert!(parse_memory_limit(bad).is_err(), "{bad}");
        }
        assert!(MemoryLimit::Bytes(-5).bytes().is_err());
        assert_eq!(show_bytes(64 << 20), "64 MiB");
    }

    #[test]
    fn factors_are_exact_fractions() {
        assert_eq!(parse_factor("7/2"), Ok((7, 2)));
        assert_eq!(parse_factor("3"), Ok((3, 1)));
        assert_eq!(parse_factor("1.25"), Ok((125, 100)));
        for bad in ["", "0", "-1", "x/2", "1/0", "NaN", "1.2.3"] {
            assert!(parse_factor(bad).is_err(), "{bad}");
        }
    }
}
