//! Progress of a run on stderr: a bar (counts and ETA) on a terminal; plain lines otherwise (a
//! Slurm log, a CI log, `2> file`), one per 5% of the instances and at least one a minute, so a
//! long run is never silent, even while a single instance takes hours.

use indicatif::{ProgressBar, ProgressStyle};
use std::io::IsTerminal;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// At least one line per this long without a terminal.
const HEARTBEAT: Duration = Duration::from_secs(60);

/// Counts finished instances and reports them.
pub struct Progress {
    inner: Inner,
}

enum Inner {
    Bar(ProgressBar),
    Lines(Arc<Lines>),
}

/// The line reporter's state, shared with its heartbeat thread.
struct Lines {
    len: u64,
    start: Instant,
    /// (finished instances, when the last line was printed)
    state: Mutex<(u64, Instant)>,
    done: AtomicBool,
}

impl Lines {
    fn line(&self, done: u64) -> String {
        let elapsed = self.start.elapsed();
        let eta = if done > 0 && done < self.len {
            let left = elapsed.as_secs_f64() / done as f64 * (self.len - done) as f64;
            format!(", ETA {}", clock(Duration::from_secs_f64(left)))
        } else {
            String::new()
        };
        format!(
            "progress: {done}/{} instances ({:.0}%), {} elapsed{eta}",
            self.len,
            if self.len == 0 {
                100.0
            } else {
                done as f64 * 100.0 / self.len as f64
            },
            clock(elapsed)
        )
    }

    fn print(&self, state: &mut (u64, Instant)) {
        eprintln!("{}", self.line(state.0));
        state.1 = Instant::now();
    }
}

/// `1h02m03s`, `2m03s` or `3s`.
fn clock(d: Duration) -> String {
    let s = d.as_secs();
    match (s / 3600, s / 60 % 60, s % 60) {
        (0, 0, s) => format!("{s}s"),
        (0, m, s) => format!("{m}m{s:02}s"),
        (h, m, s) => format!("{h}h{m:02}m{s:02}s"),
    }
}

/// Progress over `len` instances: a bar on a terminal, lines otherwise.
pub fn bar(len: u64) -> Progress {
    if std::io::stderr().is_terminal() {
        let bar = ProgressBar::new(len);
        bar.set_style(
            ProgressStyle::with_template(
                "{elapsed_precise} [{bar:40}] {pos}/{len} instances, ETA {eta}",
            )
            .expect("valid template")
            .progress_chars("=> "),
        );
        return Progress {
            inner: Inner::Bar(bar),
        };
    }
    let lines = Arc::new(Lines {
        len,
        start: Instant::now(),
        state: Mutex::new((0, Instant::now())),
        done: AtomicBool::new(false),
    });
    eprintln!("progress: 0/{len} instances");
    let heartbeat = Arc::clone(&lines);
    std::thread::spawn(move || {
        while !heartbeat.done.load(Ordering::Relaxed) {
            std::thread::sleep(Duration::from_secs(1));
            let mut state = heartbeat.state.lock().expect("progress lock");
            if !heartbeat.done.load(Ordering::Relaxed) && state.1.elapsed() >= HEARTBEAT {
                heartbeat.print(&mut state);
            }
        }
    });
    Progress {
        inner: Inner::Lines(lines),
    }
}

impl Progress {
    /// `n` more instances finished.
    pub fn inc(&self, n: u64) {
        match &self.inner {
            Inner::Bar(bar) => bar.inc(n),
            Inner::Lines(lines) => {
                let mut state = lines.state.lock().expect("progress lock");
                let before = state.0;
                state.0 += n;
                // A line each time another 5% (at least one instance) has finished.
                let step = (lines.len / 20).max(1);
                if state.0 / step != before / step || state.0 == lines.len {
                    lines.print(&mut state);
                }
            }
        }
    }

    /// The run is over: clear the bar, stop the heartbeat.
    pub fn finish_and_clear(&self) {
        match &self.inner {
            Inner::Bar(bar) => bar.finish_and_clear(),
            Inner::Lines(lines) => lines.done.store(true, Ordering::Relaxed),
        }
    }
}

impl Drop for Progress {
    fn drop(&mut self) {
        if let Inner::Lines(lines) = &self.inner {
            lines.done.store(true, Ordering::Relaxed);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines_say_count_share_and_eta() {
        let lines = Lines {
            len: 40,
            start: Instant::now(),
            state: Mutex::new((0, Instant::now())),
            done: AtomicBool::new(false),
        };
        assert_eq!(
            lines.line(10),
            "progress: 10/40 instances (25%), 0s elapsed, ETA 0s"
        );
        assert_eq!(clock(Duration::from_secs(3723)), "1h02m03s");
        assert_eq!(clock(Duration::from_secs(123)), "2m03s");
    }
}
