//! `DIR/.lock`: one run (or merge) at a time per output directory.
//!
//! The lock file holds the holder's pid on its first line, then `host=`, and under Slurm
//! `slurm_job=` and `restart=` lines. A lock is stale, and is taken over with a message, when
//! its holder is on this host and its pid is not running (or is a zombie), or when it was
//! taken by an earlier attempt of this very Slurm job (same `SLURM_JOB_ID`, lower
//! `SLURM_RESTART_COUNT`: Slurm requeues a task only after its previous attempt ended, perhaps
//! on another node). Any other lock refuses the run, naming the holder.

use crate::error::{Error, Result};
use std::path::{Path, PathBuf};

/// Holds `DIR/.lock` until dropped (also when the run fails or panics).
#[derive(Debug)]
pub struct LockGuard {
    path: PathBuf,
    content: String,
}

impl Drop for LockGuard {
    fn drop(&mut self) {
        // Only remove the lock if it is still ours (a racing takeover may have replaced it).
        if std::fs::read_to_string(&self.path).is_ok_and(|c| c == self.content) {
            let _ = std::fs::remove_file(&self.path);
        }
    }
}

/// The holder described by a lock file.
#[derive(Clone, Debug, PartialEq)]
struct Holder {
    pid: Option<i64>,
    host: Option<String>,
    slurm_job: Option<String>,
    restart: u64,
}

impl Holder {
    fn parse(text: &str) -> Holder {
        let mut lines = text.lines();
        let pid = lines.next().and_then(|l| l.trim().parse().ok());
        let mut h = Holder {
            pid,
            host: None,
            slurm_job: None,
            restart: 0,
        };
        for l in lines {
            match l.split_once('=') {
                Some(("host", v)) => h.host = Some(v.to_string()),
                Some(("slurm_job", v)) => h.slurm_job = Some(v.to_string()),
                Some(("restart", v)) => h.restart = v.parse().unwrap_or(0),
                _ => {}
            }
        }
        h
    }

    fn describe(&self) -> String {
        let mut s = match self.pid {
            Some(p) => format!("pid {p}"),
            None => "an unreadable pid".to_string(),
        };
        if let Some(h) = &self.host {
            s += &format!(" on host {h}");
        }
        if let Some(j) = &self.slurm_job {
            s += &format!(" (Slurm job {j}, restart {})", self.restart);
        }
        s
    }
}

fn hostname() -> String {
    let mut buf = [0u8; 256];
    // SAFETY: gethostname writes at most buf.len() bytes into buf.
    let ok = unsafe { libc::gethostname(buf.as_mut_ptr().cast(), buf.len()) } == 0;
    let end = buf.iter().position(|&b| b == 0).unwrap_or(buf.len());
    if ok {
        String::from_utf8_lossy(&buf[..end]).into_owned()
    } else {
        "unknown".into()
    }
}

fn slurm_restart() -> u64 {
    std::env::var("SLURM_RESTART_COUNT")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(0)
}

/// What this process writes into a lock it takes.
fn our_content() -> String {
    let mut s = format!("{}\nhost={}\n", std::process::id(), hostname());
    if let Ok(job) = std::env::var("SLURM_JOB_ID") {
        s += &format!("slurm_job={job}\nrestart={}\n", slurm_restart());
    }
    s
}

/// Whether process `pid` of this host is running: it exists (kill with signal 0 succeeds or is
/// denied) and is not a zombie.
pub fn pid_alive(pid: i64) -> bool {
    // pid 0 and negative pids would address process groups, not a process.
    let Ok(p) = libc::pid_t::try_from(pid) else {
        return false;
    };
    if p <= 0 {
        return false;
    }
    // SAFETY: signal 0 only checks that the process exists and may be signalled.
    let exists = unsafe { libc::kill(p, 0) } == 0
        || std::io::Error::last_os_error().raw_os_error() == Some(libc::EPERM);
    // A killed child its parent has not reaped yet is a zombie: it holds nothing.
    let zombie = std::fs::read_to_string(format!("/proc/{p}/stat")).is_ok_and(|s| {
        s.rsplit_once(')')
            .is_some_and(|(_, rest)| rest.trim_start().starts_with('Z'))
    });
    exists && !zombie
}

/// Why the holder of a lock is known to be gone, or `None` when it may still be running.
fn stale_reason(h: &Holder) -> Option<String> {
    let here = hostname();
    if let (Some(job), Ok(our_job)) = (&h.slurm_job, std::env::var("SLURM_JOB_ID"))
        && *job == our_job
        && h.restart < slurm_restart()
    {
        return Some(format!(
            "taken by an earlier attempt of Slurm job {job} (restart {} < {})",
            h.restart,
            slurm_restart()
        ));
    }
    if h.host.as_deref().is_none_or(|host| host == here) {
        return match h.pid {
            Some(p) if !pid_alive(p) => Some(format!("pid {p} is not running")),
            _ => None,
        };
    }
    None
}

/// Takes `dir/.lock` (the directory must exist). A lock held by a running process refuses
/// with an error naming the holder; a stale one is taken over, saying so on stderr.
pub fn acquire(dir: &Path) -> Result<LockGuard> {
    let path = dir.join(".lock");
    let content = our_content();
    // Written in full to a private file, then hard-linked into place: the link fails if a lock
    // exists, and a lock is never seen half-written.
    let tmp = dir.join(format!(".lock.{}", std::process::id()));
    std::fs::write(&tmp, &content).map_err(|e| Error::io(&tmp, e))?;
    let result = acquire_with(&path, &tmp, &content);
    let _ = std::fs::remove_file(&tmp);
    result
}

fn acquire_with(path: &Path, tmp: &Path, content: &str) -> Result<LockGuard> {
    let guard = || LockGuard {
        path: path.to_path_buf(),
        content: content.to_string(),
    };
    match std::fs::hard_link(tmp, path) {
        Ok(()) => return Ok(guard()),
        Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => {}
        Err(e) => return Err(Error::io(path, e)),
    }
    let held = std::fs::read_to_string(path).map_err(|e| Error::io(path, e))?;
    let holder = Holder::parse(&held);
    let Some(why) = stale_reason(&holder) else {
        return Err(Error::invalid(format!(
            "{}: another mowmill run holds this directory ({}); wait for it to finish, or \
             remove {} if that run is gone",
            path.display(),
            holder.describe(),
            path.display()
        )));
    };
    // Move the stale lock aside and check that what moved is the lock judged stale: two runs
    // taking over at once cannot both win.
    let aside = path.with_extension(format!("stale.{}", std::process::id()));
    std::fs::rename(path, &aside).map_err(|e| Error::io(path, e))?;
    let moved = std::fs::read_to_string(&aside).unwrap_or_default();
    if moved != held {
        let _ = std::fs::hard_link(&aside, path);
        let _ = std::fs::remove_file(&aside);
        return Err(Error::invalid(format!(
            "{}: another mowmill run took this directory over just now ({})",
            path.display(),
            Holder::parse(&moved).describe()
        )));
    }
    let _ = std::fs::remove_file(&aside);
    match std::fs::hard_link(tmp, path) {
        Ok(()) => {
            eprintln!(
                "mowmill: taking over the stale lock {} ({}: {why})",
                path.display(),
                holder.describe()
            );
            Ok(guard())
        }
        Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => Err(Error::invalid(format!(
            "{}: another mowmill run took this directory over just now",
            path.display()
        ))),
        Err(e) => Err(Error::io(path, e)),
    }
}
