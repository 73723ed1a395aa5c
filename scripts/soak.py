#!/usr/bin/env python3
"""The soak's command-line half (docs/soak.md); run it through scripts/soak.sh.

    python3 scripts/soak.py --bin target/release/mowmill --out DIR --seed S --probes K

Runs K probes, each one mowmill command on a mutated input (or a mutated numeric argument),
under a 2 GiB address-space limit and a wall-clock timeout, and counts panics (exit 101 or
"panicked"), aborts (a signal, an exit >= 128, or an exit code mowmill does not use), hangs (the
timeout) and false passes (exit 0 with a result that scripts/tour_check.py disagrees with).
Every failing probe keeps its folder under DIR/probes/ (command, input, stdout, stderr); the
others are removed. Deterministic for a given seed.
"""

import argparse
import json
import os
import random
import resource
import shutil
import signal
import subprocess
import sys
import zlib
from concurrent.futures import ThreadPoolExecutor

sys.dont_write_bytecode = True  # No __pycache__ in scripts/: the soak writes only under --out.
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import tour_check  # noqa: E402

HUGE = ["100000", "2147483647", "-2147483648", "2147483648", "4294967296", "9223372036854775807",
        "-9223372036854775808", "99999999999999999999999", "1e300", "-1e300", "NaN", "inf",
        "-1", "0", "50000000", ""]
SPECIAL = b"\n#;,-.()[]{}\"=:e ---"
MILLING_ALGOS = ["star-cover", "milling-2opt", "tsp65", "strips-double", "milling25"]
OTHER_ALGOS = ["lawn-box", "lawn-mst", "boundary-cc", "thin-cc", "strips-matching"]
MEMORY = 2 << 30


def mutate(data, rng):
    b = bytearray(data)
    for _ in range(rng.randint(1, 4)):
        kind = rng.randrange(8)
        at = rng.randrange(len(b) + 1)
        if kind == 0 and b:
            b[rng.randrange(len(b))] ^= 1 << rng.randrange(8)
        elif kind == 1:
            del b[at:]
        elif kind == 2:
            start = b.rfind(b"\n", 0, at) + 1
            end = b.find(b"\n", at)
            end = len(b) if end < 0 else end + 1
            line = bytes(b[start:end])
            b[end:end] = line * rng.randint(1, 4)
        elif kind == 3:
            tok = set(b"abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789.-")
            start = at
            while start > 0 and b[start - 1] in tok:
                start -= 1
            end = at
            while end < len(b) and b[end] in tok:
                end += 1
            b[start:end] = rng.choice(HUGE).encode()
        elif kind == 4:
            del b[at:at + rng.randint(1, 16)]
        elif kind == 5:
            b[at:at] = bytes([rng.randrange(256)])
        elif kind == 6:
            b[at:at] = bytes([rng.choice(SPECIAL)])
        else:
            n = rng.randrange(32)
            chunk = bytes(b[at:at + n])
            del b[at:at + n]
            to = rng.randrange(len(b) + 1)
            b[to:to] = chunk
    return bytes(b)


class Soak:
    def __init__(self, args):
        self.bin = os.path.abspath(args.bin)
        self.out = os.path.abspath(args.out)
        self.timeout = args.timeout
        self.seed = args.seed
        self.seeds = os.path.join(self.out, "seeds")
        self.env = dict(os.environ, TMPDIR=os.path.join(self.out, "tmp"))
        for k in list(self.env):
            if k.startswith("SLURM_"):
                del self.env[k]

    def run(self, argv, cwd):
        """(returncode or None on timeout, stdout, stderr) under the memory cap."""
        def limit():
            resource.setrlimit(resource.RLIMIT_AS, (MEMORY, MEMORY))
            resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
        p = subprocess.Popen(argv, cwd=cwd, env=self.env, stdin=subprocess.DEVNULL,
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             preexec_fn=limit, start_new_session=True)
        try:
            out, err = p.communicate(timeout=self.timeout)
            rc = p.returncode
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL)
            out, err = p.communicate()
            rc = None
        try:  # Children left behind by the command (an outside program, a solver thread).
            os.killpg(p.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        return rc, out, err

    def setup(self):
        """Seed files: the committed fixtures, generated lattices, tours and a tiny bench run."""
        os.makedirs(self.seeds, exist_ok=True)
        os.makedirs(self.env["TMPDIR"], exist_ok=True)
        repo = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
        s = self.seeds
        for f in ["fixtures/two-holes.grid", "fixtures/square-3x3.grid",
                  "fixtures/square-3x3.tour.json", "fixtures/tailed-frame.grid",
                  "fixtures/rect-2x3.grid", "fixtures/rect-2x3.tour.json",
                  "fixtures/peers/l-shape.gg", "fixtures/peers/notched-frame.poly",
                  "discrete/bridge.dm", "discrete/hub-first.dm"]:
            shutil.copy(os.path.join(repo, "instances", f), s)
        with open(os.path.join(s, "wrap.gg"), "w") as f:  # Pixels at both ends of i32.
            f.write("2147483647 0\n-2147483648 0\n")
        with open(os.path.join(s, "wrap.tour.json"), "w") as f:
            f.write('{"cycles": [[[2147483647, 0], [-2147483648, 0]]]}\n')
        with open(os.path.join(s, "far.gg"), "w") as f:  # Far-apart pixels (lawn algorithms).
            f.write("0 0\n1 0\n2000000000 2000000000\n2000000001 2000000000\n")
        with open(os.path.join(s, "tiny.toml"), "w") as f:
            f.write('name = "soak"\nseed = 1\n\n[[family]]\nfamily = "rect"\n'
                    'width = [2, 3]\nheight = 2\n\n[[exact]]\nobjective = "turns"\n'
                    'max_n = 10\ntime_limit = 2\n')
        steps = [
            ["gen", "voxel", "--n", "8", "--seed", "1", "--out", "a.vox"],
            ["gen", "hex", "--n", "8", "--seed", "1", "--out", "a.hex"],
            ["gen", "random-holed", "--n", "30", "--holes", "1", "--seed", "3", "--out", "b.wkt"],
            ["gen", "random-simple", "--n", "20", "--seed", "2", "--out", "c.csv"],
            ["export", "rect-2x3.grid", "--format", "dm-json", "--out", "rect.json"],
            ["solve", "a.vox", "--algo", "star-cover", "--tour-out", "a.vox.tour.json"],
            ["solve", "bridge.dm", "--algo", "star-cover", "--tour-out", "bridge.tour.json"],
            ["solve", "two-holes.grid", "--algo", "star-cover", "--tour-out",
             "two-holes.tour.json"],
            ["bench", "--config", "tiny.toml", "--out", "run", "--jobs", "1"],
        ]
        for argv in steps:
            rc, _, err = self.run([self.bin] + argv, s)
            if rc not in (0, 1):
                sys.exit(f"soak: set-up step `mowmill {' '.join(argv)}` failed ({rc}): "
                         f"{err.decode(errors='replace')[-400:]}")
        self.instances = {
            "grid": ["two-holes.grid", "square-3x3.grid", "tailed-frame.grid"],
            "gg": ["l-shape.gg", "wrap.gg", "far.gg"], "csv": ["c.csv"],
            "wkt": ["b.wkt"], "poly": ["notched-frame.poly"],
            "dm": ["bridge.dm", "hub-first.dm"], "json": ["rect.json"],
            "vox": ["a.vox"], "hex": ["a.hex"],
        }
        self.tours = [("square-3x3.grid", "square-3x3.tour.json"),
                      ("rect-2x3.grid", "rect-2x3.tour.json"),
                      ("two-holes.grid", "two-holes.tour.json"),
                      ("wrap.gg", "wrap.tour.json")]
        self.discrete_tours = [("a.vox", "a.vox.tour.json"), ("bridge.dm", "bridge.tour.json")]

    def seed_path(self, name):
        return os.path.join(self.seeds, name)

    def special(self, kind, path):
        """An input that is not a regular file: empty, a directory, /dev/zero, a FIFO."""
        if kind == "empty":
            open(path, "wb").close()
        elif kind == "dir":
            os.makedirs(path)
        elif kind == "devzero":
            os.symlink("/dev/zero", path)
        elif kind == "fifo":
            os.mkfifo(path)

    def plan(self, count):
        """The probes: (id, kind, description, builder). Deterministic for the seed."""
        rng = random.Random(self.seed)
        probes = []
        fixed = [
            ("validate", "wrap.gg", "wrap.tour.json"),
        ] + [("solve-far", "far.gg", a) for a in
             ["lawn-box", "lawn-mst", "lawn-christofides", "lawn-2opt", "star-cover"]]
        for f in fixed:
            probes.append(("fixed",) + f)
        # Numeric arguments at the edges, every value once.
        args = [
            ["exact", "@two-holes.grid", "--objective", "turns", "--time-limit", "{V}"],
            ["exact", "@square-3x3.grid", "--objective", "length", "--time-limit", "1",
             "--threads", "{V}"],
            ["exact", "@square-3x3.grid", "--objective", "weighted", "--turn-cost", "{V}",
             "--time-limit", "1"],
            ["solve", "@two-holes.grid", "--algo", "star-cover", "--objective", "weighted",
             "--turn-cost", "{V}"],
            ["gen", "rect", "--width", "{V}", "--height", "2", "--out", "{P}/g.grid"],
            ["gen", "eroded", "--n", "{V}", "--seed", "1", "--out", "{P}/g.grid"],
            ["hunt", "--algo", "star-cover", "--min-n", "4", "--max-n", "8", "--evaluations",
             "4", "--seed", "1", "--jobs", "{V}", "--out", "{P}/hunt"],
            ["gate", "--baseline", "@run/stats.csv", "--current", "@run", "--tolerance", "{V}"],
        ]
        for a in args:
            for v in (HUGE if count >= 1000 else ["2147483647", "-1", "1e300", "NaN", "0",
                                                   "100000"]):
                probes.append(("arg", a, v))
        specials = ["empty", "dir", "devzero", "fifo"]
        for sp in specials:
            for cmd in ["info", "solve", "validate-instance", "validate-tour", "exact",
                        "draw", "export", "config", "results:gate", "results:gate-baseline",
                        "results:claims", "results:plot", "results:merge"]:
                probes.append(("special", cmd, sp))
        kinds = ["instance"] * 6 + ["tour"] * 3 + ["dtour", "config", "results", "results"]
        while len(probes) < count:
            probes.append(("random", rng.choice(kinds), rng.randrange(1 << 30)))
        return probes

    def build(self, probe, pdir):
        """(argv, input path, checks) for one probe, its files written under pdir."""
        P = pdir
        mow = [self.bin]
        kind = probe[0]
        if kind == "fixed":
            _, what, inst, extra = probe
            if what == "validate":
                shutil.copy(self.seed_path(inst), P)
                shutil.copy(self.seed_path(extra), P)
                i, t = os.path.join(P, inst), os.path.join(P, extra)
                return mow + ["validate", i, "--tour", t, "--json"], t, ("validate", i, t)
            shutil.copy(self.seed_path(inst), P)
            i = os.path.join(P, inst)
            return mow + ["solve", i, "--algo", extra, "--json"], i, None
        if kind == "arg":
            _, a, v = probe
            argv = []
            for x in a:
                if x.startswith("@"):
                    x = self.seed_path(x[1:])
                argv.append(x.replace("{V}", v).replace("{P}", P))
            return mow + argv, None, None
        if kind == "special":
            _, cmd, sp = probe
            return self.build_cmd(cmd, P, None, sp, random.Random(zlib.crc32(f"{cmd}/{sp}".encode())))
        _, what, s = probe
        rng = random.Random(s)
        return self.build_cmd(what, P, rng, None, rng)

    def build_cmd(self, what, P, rng, special, r):
        mow = [self.bin]

        def make(seed_name, ext):
            path = os.path.join(P, "input." + ext)
            if special:
                self.special(special, path)
            else:
                data = open(self.seed_path(seed_name), "rb").read()
                with open(path, "wb") as f:
                    f.write(mutate(data, rng))
            return path

        if what in ("instance", "info", "solve", "exact", "draw", "export", "validate-instance"):
            ext = r.choice(sorted(self.instances))
            inst = r.choice(self.instances[ext])
            i = make(inst, ext)
            discrete = ext in ("dm", "json", "vox", "hex")
            cmd = what if what != "instance" else r.choice(
                ["info", "solve", "solve", "exact", "draw", "export", "validate-instance"])
            if cmd == "info":
                return mow + ["info", i] + r.choice([[], ["--json"]]), i, None
            if cmd == "solve":
                algo = "star-cover" if discrete else r.choice(MILLING_ALGOS + OTHER_ALGOS)
                t = os.path.join(P, "tour.json")
                checks = None
                if not discrete and algo in MILLING_ALGOS and ext in ("grid", "gg", "csv"):
                    checks = ("solve", i, t)
                return (mow + ["solve", i, "--algo", algo, "--json", "--tour-out", t], i, checks)
            if cmd == "exact":
                obj = r.choice(["turns", "length", "cc-turns"])
                return (mow + ["exact", i, "--objective", obj, "--time-limit", "1",
                               "--threads", "1", "--json"], i, None)
            if cmd == "draw":
                return mow + ["draw", i, "--out", os.path.join(P, "x.svg")], i, None
            if cmd == "export":
                fmt = r.choice(["gg", "wkt", "grid", "tsplib", "dm", "dm-json"])
                return mow + ["export", i, "--format", fmt, "--out",
                              os.path.join(P, "out." + fmt)], i, None
            # validate a good tour against a mutated instance
            pairs = self.discrete_tours if discrete else self.tours
            t = self.seed_path(r.choice(pairs)[1])
            return mow + ["validate", i, "--tour", t, "--json"], i, None
        if what in ("tour", "validate-tour"):
            inst, tour = r.choice(self.tours)
            i = self.seed_path(inst)
            t = make(tour, "json")
            cmd = "validate" if what == "validate-tour" else r.choice(
                ["validate"] * 4 + ["draw", "exact"])
            if cmd == "validate":
                mode = r.choice([[], [], ["--mode", "lawn"]])
                checks = ("validate", i, t) if not mode else None
                return mow + ["validate", i, "--tour", t, "--json"] + mode, t, checks
            if cmd == "draw":
                return mow + ["draw", i, "--tour", t, "--out", os.path.join(P, "x.png")], t, None
            return (mow + ["exact", i, "--objective", "length", "--start", t, "--time-limit",
                           "1", "--threads", "1"], t, None)
        if what == "dtour":
            inst, tour = r.choice(self.discrete_tours)
            t = make(tour, "json")
            return mow + ["validate", self.seed_path(inst), "--tour", t, "--json"], t, None
        if what == "config":
            c = make("tiny.toml", "toml")
            return (mow + ["bench", "--config", c, "--out", os.path.join(P, "run"), "--jobs",
                           "1"], c, None)
        # results: a copy of the tiny run with one file mutated (or replaced by a special one)
        d = os.path.join(P, "run")
        shutil.copytree(self.seed_path("run"), d, symlinks=True)
        cmd = what.split(":")[1] if ":" in what else r.choice(
            ["gate", "gate-baseline", "claims", "plot", "merge"])
        name = ("stats.csv" if cmd == "gate-baseline" else "results.csv") if special else r.choice(
            ["results.csv", "results.csv", "stats.csv", "manifest.json"])
        target = os.path.join(d, name)
        if special:
            os.remove(target)
            self.special(special, target)
        else:
            data = open(target, "rb").read()
            with open(target, "wb") as f:
                f.write(mutate(data, rng))
        base = self.seed_path("run")
        if cmd == "gate":
            argv = ["gate", "--baseline", os.path.join(base, "stats.csv"), "--current", d]
        elif cmd == "gate-baseline":
            argv = ["gate", "--baseline", os.path.join(d, "stats.csv"), "--current", base]
        elif cmd == "claims":
            argv = ["claims", "--from", d, "--hunt", os.path.join(P, "no-hunt"), "--out",
                    os.path.join(P, "claims")]
        elif cmd == "plot":
            argv = ["plot", d]
        else:
            argv = ["merge", d, base, "--out", os.path.join(P, "merged")]
        return mow + argv, target, None

    def false_pass(self, checks, out):
        """Why an exit-0 result is wrong, or None; only where tour_check.py can recount."""
        what, inst, tour = checks
        try:
            report = json.loads(out)
        except ValueError:
            return None if what == "solve" else "validate --json printed no JSON"
        try:
            region = tour_check.read_region(inst)
        except (ValueError, UnicodeDecodeError, OSError):
            return None  # A mutated instance Python cannot read: nothing to compare.
        try:
            tour_data = json.load(open(tour, encoding="utf-8"))
            valid, length, turns, error = tour_check.check(region, tour_data)
        except (ValueError, KeyError, TypeError, UnicodeDecodeError, OSError) as e:
            valid, length, turns, error = False, None, None, f"malformed tour ({e})"
        if not valid:
            return f"mowmill says valid; tour_check.py: {error}"
        if (report.get("length"), report.get("turns")) != (length, turns):
            return (f"mowmill length {report.get('length')}, turns {report.get('turns')}; "
                    f"tour_check.py length {length}, turns {turns}")
        return None

    def probe(self, index, probe):
        pdir = os.path.join(self.out, "probes", f"{index:05d}")
        os.makedirs(pdir)
        argv, inp, checks = self.build(probe, pdir)
        rc, out, err = self.run(argv, pdir)
        verdict = None
        if rc is None:
            verdict = "hang"
        elif rc == 101 or b"panicked" in err:
            verdict = "panic"
        elif rc < 0 or rc >= 128 or rc not in (0, 1, 2, 3):
            verdict = "abort"
        elif rc == 0 and checks and (argv[1] == "validate" or os.path.exists(checks[2])):
            why = self.false_pass(checks, out)
            if why:
                verdict = "false pass"
                err += f"\nsoak: false pass: {why}\n".encode()
        shown = " ".join(argv).replace(self.bin, "mowmill")
        if verdict is None:
            shutil.rmtree(pdir, ignore_errors=True)
            return None
        with open(os.path.join(pdir, "command.txt"), "w") as f:
            f.write(shown + "\n")
        with open(os.path.join(pdir, "stdout"), "wb") as f:
            f.write(out[-100000:])
        with open(os.path.join(pdir, "stderr"), "wb") as f:
            f.write(err[-100000:])
        first = err.decode(errors="replace").strip().splitlines()
        marks = ("panicked", "soak:", "memory allocation", "error:", "overflow", "fatal")
        note = next((l for l in first if any(m in l for m in marks)), first[0] if first else "")
        return verdict, rc, shown, inp, note[:300]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--probes", type=int, default=200)
    ap.add_argument("--timeout", type=float, default=20)
    ap.add_argument("--jobs", type=int, default=2)
    args = ap.parse_args()
    soak = Soak(args)
    soak.setup()
    probes = soak.plan(args.probes)
    with ThreadPoolExecutor(args.jobs) as pool:
        results = list(pool.map(lambda ip: soak.probe(*ip), enumerate(probes)))
    counts = {"panics": 0, "aborts": 0, "hangs": 0, "false passes": 0}
    key = {"panic": "panics", "abort": "aborts", "hang": "hangs", "false pass": "false passes"}
    lines = []
    for i, res in enumerate(results):
        if res is None:
            continue
        verdict, rc, shown, inp, note = res
        counts[key[verdict]] += 1
        lines.append(f"{verdict.upper()} (exit {rc if rc is not None else 'timeout'}) "
                     f"probe {i:05d}: {shown}\n    input: {inp or '(the arguments)'}\n"
                     f"    {note}")
    shutil.rmtree(soak.env["TMPDIR"], ignore_errors=True)
    summary = (f"probes {len(probes)}, panics {counts['panics']}, aborts {counts['aborts']}, "
               f"hangs {counts['hangs']}, false passes {counts['false passes']}")
    text = "\n".join(lines + [summary]) + "\n"
    with open(os.path.join(soak.out, "report.txt"), "w") as f:
        f.write(text)
    sys.stdout.write(text)
    sys.exit(1 if any(counts.values()) else 0)


if __name__ == "__main__":
    main()
