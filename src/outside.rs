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
//!   tour file is an error row; a walk the checker rejects is a row with `valid = false`.

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
    /// The folder the program runs in.
    pub dir: PathBuf,
}

/// The largest tour file read back (bytes): far above any walk of a region within the pixel
/// limit at the lengths the papers' algorithms reach, far below what would exhaust memory.
const MAX_TOUR_BYTES: u64 = 1 << 30;

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
        let objectives: Vec<Objective> = spec
            .objectives
            .iter()
            .map(|o| o.parse::<Objective>())
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
                measure: Measure::Bound(Bound {
                    quantity: Quantity::Value,
                    num,
                    den,
                    add: 0,
                    against,
                    scale: crate::algorithms::Scale::One,
                }),
                when: When::Always,
                realized: Realized::ByAlgorithms,
                tight: None,
            }));
            guarantees.push(Guarantee {
                theorem,
                objective,
                quantity: Quantity::Value,
                num,
                den,
                add: 0,
                against,
                when: When::Always,
                scale: crate::algorithms::Scale::One,
                source,
            });
        }
        Ok(OutsideAlgorithm {
            name: spec.name.clone(),
            command: spec.command.clone(),
            objectives,
            guarantees,
            time_limit: spec.time_limit,
            dir: dir.to_path_buf(),
        })
    }

    /// Runs the program on `region` for `objectives` and reads its walks back.
    pub fn run(&self, region: &Region, objectives: &[Objective]) -> Result<Solution> {
        let work = TempDir::new(&self.name)?;
        let instance = work.path.join("instance.grid");
        // The .grid format has no negative coordinates: shift the region into the quadrant
        // and the walks back.
        let b = region.bbox();
        let (dx, dy) = ((-b.min_x).max(0), (-b.min_y).max(0));
        let shifted = region.translated(dx, dy)?;
        GridFile::with_meta(shifted, &[]).write(&instance)?;
        let per_objective = self.command.iter().any(|a| a.contains("{objective}"));
        let mut solution = Solution::default();
        if per_objective {
            for &objective in objectives {
                let cover = self.run_once(region, &work.path, &instance, Some(objective))?;
                let cover = shift(cover, -dx, -dy);
                solution.outputs.push(Output { objective, cover });
            }
        } else {
            let cover = shift(
                self.run_once(region, &work.path, &instance, None)?,
                -dx,
                -dy,
            );
            for &objective in objectives {
                solution.outputs.push(Output {
                    objective,
                    cover: cover.clone(),
                });
            }
        }
        Ok(solution)
    }

    fn run_once(
        &self,
        region: &Region,
        work: &Path,
        instance: &Path,
        objective: Option<Objective>,
    ) -> Result<CycleCover> {
        let tag = objective.map_or("all".to_string(), |o| o.to_string());
        let tour_out = work.join(format!("tour-{tag}.json"));
        let fill = |a: &str| {
            a.replace("{instance}", &instance.display().to_string())
                .replace("{tour_out}", &tour_out.display().to_string())
                .replace("{objective}", objective.map_or("", |o| o.name()))
        };
        let args: Vec<String> = self.command.iter().map(|a| fill(a)).collect();
        let stderr_path = work.join(format!("stderr-{tag}.txt"));
        let stderr = std::fs::File::create(&stderr_path).map_err(|e| Error::io(&stderr_path, e))?;
        let mut cmd = Command::new(&args[0]);
        cmd.args(&args[1..])
            .current_dir(&self.dir)
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(stderr)
            .env("MOWMILL_INSTANCE", instance)
            .env("MOWMILL_TOUR_OUT", &tour_out)
            .env("MOWMILL_OBJECTIVE", objective.map_or("", |o| o.name()))
            .env("MOWMILL_TIME_LIMIT", self.time_limit.to_string())
            .env("MOWMILL_N", region.len().to_string());
        #[cfg(unix)]
        {
            use std::os::unix::process::CommandExt;
            cmd.process_group(0);
        }
        let mut child = cmd.spawn().map_err(|e| {
            Error::solver(format!(
                "{}: cannot start {:?} (in {}): {e}",
                self.name,
                args[0],
                self.dir.display()
            ))
        })?;
        let start = Instant::now();
        let limit = Duration::from_secs_f64(self.time_limit);
        let status = loop {
            match child.try_wait() {
                Ok(Some(status)) => break status,
                Ok(None) if start.elapsed() > limit => {
                    kill_group(&mut child);
                    return Err(Error::solver(format!(
                        "{}: time limit of {} s exceeded; killed",
                        self.name, self.time_limit
                    )));
                }
                Ok(None) => std::thread::sleep(Duration::from_millis(5)),
                Err(e) => return Err(Error::solver(format!("{}: {e}", self.name))),
            }
        };
        if !status.success() {
            return Err(Error::solver(format!(
                "{}: exited with {status}{}",
                self.name,
                stderr_tail(&stderr_path)
            )));
        }
        let size = std::fs::metadata(&tour_out)
            .map_err(|_| {
                Error::invalid_output(format!(
                    "{}: exited 0 but wrote no tour file ({{tour_out}}){}",
                    self.name,
                    stderr_tail(&stderr_path)
                ))
            })?
            .len();
        if size > MAX_TOUR_BYTES {
            return Err(Error::invalid_output(format!(
                "{}: tour file of {size} bytes is above the limit of {MAX_TOUR_BYTES}",
                self.name
            )));
        }
        CycleCover::read(&tour_out)
            .map_err(|e| Error::invalid_output(format!("{}: malformed tour: {e}", self.name)))
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

/// The last lines of a program's stderr, for the error message.
fn stderr_tail(path: &Path) -> String {
    let text = std::fs::read(path).unwrap_or_default();
    let tail = &text[text.len().saturating_sub(600)..];
    let tail = String::from_utf8_lossy(tail);
    let tail = tail.trim();
    if tail.is_empty() {
        String::new()
    } else {
        format!("; stderr: {}", tail.replace('\n', " | "))
    }
}

fn kill_group(child: &mut std::process::Child) {
    #[cfg(unix)]
    // SAFETY: kill(2) on the process group the child leads (process_group(0) above).
    unsafe {
        libc::kill(-(child.id() as i32), libc::SIGKILL);
    }
    let _ = child.kill();
    let _ = child.wait();
}

/// A scratch folder removed on drop.
struct TempDir {
    path: PathBuf,
}

impl TempDir {
    fn new(tag: &str) -> Result<TempDir> {
        use std::sync::atomic::{AtomicU64, Ordering};
        static COUNTER: AtomicU64 = AtomicU64::new(0);
        let k = COUNTER.fetch_add(1, Ordering::Relaxed);
        let safe: String = tag
            .chars()
            .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
            .collect();
        let path = std::env::temp_dir().join(format!("mowmill-{safe}-{}-{k}", std::process::id()));
        std::fs::create_dir_all(&path).map_err(|e| Error::io(&path, e))?;
        Ok(TempDir { path })
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.path);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
