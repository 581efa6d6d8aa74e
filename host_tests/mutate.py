#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""host_tests/mutate.py: the mutation gate (make mutate, make mutate-quick).

Applies each mutation of host_tests/mutations.txt to a scratch copy of lib/,
one at a time, builds the library from the copy (the units that include the
mutated file; the others' objects are built once from lib/), links the fast
suites against it and runs them in order until one fails (the mutant is
"killed").
A mutant that every suite passes "survived": a bug the tests would not see.
Mutants marked `equivalent:` (with the argument why no test can tell them
from the original) must survive; one that is killed is a list error.

The fast suites: the host cmocka suites (unit, scene, config, engine, GSL,
vectors, critical states, fit, engine vs ref, q31), the q31 trace against its
committed fingerprint (host_tests/q31_trace.expected), the CLI contract and
the short stress and critical-state sweeps. A suite that runs past its time limit (a mutant that loops
until an iteration cap, or forever) counts as killing it.

Usage: mutate.py [--quick] [--jobs N] [--only ID[,ID...]] [--keep]
  --quick  only the entries marked `quick: yes` (one per module; make test)
  --jobs   mutants built and run at once (default 2)
  --only   the named entries
  --keep   keep each mutant's scratch directory (build/mutate/m/<id>)
Exit status: 0 when no mutant survives but the equivalent ones and the list
is consistent; 1 otherwise; 2 on a malformed list.

Standard library only (any python3).
"""
import concurrent.futures as cf
import os
import re
import shutil
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
B = os.path.join(ROOT, "build", "mutate")
LIST = os.path.join(ROOT, "host_tests", "mutations.txt")

WARN_LIB = ["-std=c99", "-ffreestanding", "-fno-math-errno", "-ffunction-sections",
            "-fdata-sections", "-O1", "-w"]
TEST_CFLAGS = ["-std=c99", "-D_GNU_SOURCE", "-O1", "-w"]
UNITS = ["mdr_f32", "mdr_f64", "mdr_q31", "mdr_status"]
GSL = ["-lgsl", "-lgslcblas", "-lm"]

# suites that include kernels of lib/src (test_q31: the q31 rounding
# shifts, with the library's -fno-math-errno, mk/tests.mk's test_cflags):
# their flags, and the files whose mutants they see only when compiled
# against the mutant's lib/src (then from source, like a header's mutant)
SUITE_CFLAGS = {"test_q31": ["-fno-math-errno"]}
KERNEL_FILES = {"test_q31": ["lib/src/engine/mdr_engine_q31.inc", "lib/src/mdr_arith_q31.h"]}

# (name, sources, extra objects, libraries, command after the binary, time limit s)
SUITES = [
    ("test_unit", ["host_tests/test_unit.c"], [], ["-lcmocka", "-lm"], [], 60),
    ("test_scene", ["host_tests/test_scene.c"], [], ["-lcmocka", "-lm"], [], 60),
    ("test_step", ["host_tests/test_step.c"], [], ["-lcmocka", "-lm"], [], 60),
    ("test_config", ["host_tests/test_config.c"], [], ["-lcmocka", "-lm"], [], 60),
    ("test_engine", ["host_tests/test_engine.c"], ["gen_tip"], ["-lcmocka", "-lm"], [], 60),
    ("test_gsl", ["host_tests/test_gsl.c"], ["ref"], ["-lcmocka"] + GSL, [], 60),
    ("q31_trace", ["host_tests/q31_trace.c"], [], ["-lm"], [], 60),
    ("test_vectors", ["host_tests/test_vectors.c"], [], ["-lcmocka", "-lm"], [], 60),
    ("test_critical", ["host_tests/test_critical.c"], [], ["-lcmocka", "-lm"], [], 60),
    ("test_fit", ["host_tests/test_fit.c"], [], ["-lcmocka", "-lm"], [], 120),
    ("cli", ["examples/mdr_cli.c"], [], ["-lm"], [], 180),
    ("cli_f32", ["examples/mdr_cli.c"], [], ["-lm"], [], 180),
    ("fit_cli", ["examples/mdr_cli.c"], [], ["-lm", "-pthread"], [], 120),
    ("test_engine_ref", ["host_tests/test_engine_ref.c"], ["ref"], ["-lcmocka"] + GSL, [], 90),
    ("test_q31", ["host_tests/test_q31.c"], ["ref"], ["-lcmocka"] + GSL, [], 120),
    ("stress", ["host_tests/stress.c"], [], ["-lm"], ["short"], 120),
    ("crit_sweep", ["host_tests/crit_sweep.c"], [], ["-lm"], ["short"], 60),
]

# the CLI's suites: the script each runs with the mutant's CLI
CLI_SCRIPTS = {"cli": "host_tests/test_cli.sh", "cli_f32": "host_tests/test_cli_f32.sh",
               "fit_cli": "host_tests/test_fit_cli.sh"}

# The suites most likely to kill a mutant of each module run first (a survivor
# still meets every suite: the order only saves time; q31's trace compares the
# committed fingerprint, bit for bit, in a second).
FIRST = {
    "math": ["test_unit"],
    "profile": ["test_unit", "test_gsl"],
    "equilibrium": ["test_unit"],
    "stress": ["test_unit", "test_gsl"],
    "critical": ["test_unit", "test_critical"],
    "table": ["test_engine", "test_step"],
    "engine": ["q31_trace", "test_step", "test_engine"],
    "q31": ["q31_trace", "test_step", "test_q31"],
    "scene": ["test_scene", "test_step"],
    "status": ["test_unit", "cli"],
    "fit": ["test_fit", "fit_cli"],
}


def suites_for(module):
    first = FIRST.get(module, [])
    return sorted(SUITES, key=lambda s: first.index(s[0]) if s[0] in first else len(first))


def parse_list(path):
    entries, cur, errors = [], None, []
    with open(path) as fp:
        for no, line in enumerate(fp, 1):
            line = line.rstrip("\n")
            if line.startswith("#"):
                continue
            if not line.strip():
                if cur:
                    entries.append(cur)
                    cur = None
                continue
            key, sep, val = line.partition(": ")
            if not sep:
                key, sep, val = line.partition(":")
            if not sep or key not in ("id", "module", "file", "old", "new", "quick", "why",
                                      "equivalent"):
                errors.append("%s:%d: not 'key: value' with a known key" % (path, no))
                continue
            if key == "id":
                if cur:
                    entries.append(cur)
                cur = {"line": no}
            elif cur is None:
                errors.append("%s:%d: an entry starts with id:" % (path, no))
                continue
            cur[key] = val
    if cur:
        entries.append(cur)
    for e in entries:  # a literal \n in old or new stands for a line break
        for k in ("old", "new"):
            if k in e:
                e[k] = e[k].replace("\\n", "\n")
    seen = set()
    for e in entries:
        for k in ("id", "module", "file", "old", "new"):
            if k not in e:
                errors.append("%s:%d: entry without %s" % (path, e["line"], k))
        if e.get("id") in seen:
            errors.append("%s:%d: duplicate id %s" % (path, e["line"], e.get("id")))
        seen.add(e.get("id"))
    return entries, errors


def run(cmd, cwd=None, timeout=None, env=None):
    return subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          timeout=timeout, env=env)


# A cmocka suite stops at a mutant's first failed assertion (CMOCKA_TEST_ABORT:
# the failure aborts the process, which kills the mutant, instead of running
# the suite's other tests; a surviving mutant runs every test either way)
ABORT_ENV = dict(os.environ, CMOCKA_TEST_ABORT="1")


def check_entry(e):
    """The old text must occur exactly once in the file; returns an error or None."""
    path = os.path.join(ROOT, e["file"])
    if not os.path.isfile(path):
        return "%s: no file %s" % (e["id"], e["file"])
    if not e["file"].startswith("lib/"):
        return "%s: mutations apply to lib/ only" % e["id"]
    text = open(path).read()
    n = text.count(e["old"])
    if n != 1:
        return "%s: the old text occurs %d times in %s (must be once)" % (e["id"], n, e["file"])
    if e["old"] == e["new"]:
        return "%s: old and new are the same" % e["id"]
    return None


# the library's units compiled once from the real lib/ (B/obj/lib_<unit>.o)
# and the files each includes (gcc -MM): a mutant recompiles only the units
# whose sources include its file and links the others' objects (a mutant of
# lib/src/mdr_status.c compiles one unit of four; of the float modules, two)
UNIT_DEPS = {}


def unit_obj(u):
    return os.path.join(B, "obj", "lib_" + u + ".o")


def prebuild_units(workers):
    inc = ["-Ilib/include", "-Iport/host"]

    def one(u):
        src = os.path.join("lib/src", u + ".c")
        r = run(["gcc"] + WARN_LIB + inc + ["-MM", "-MT", "x", src], cwd=ROOT)
        if r.returncode != 0:
            return "mutate: cannot list the includes of %s:\n%s" % (src, r.stdout.decode())
        deps = r.stdout.decode().replace("\\\n", " ").split(":", 1)[1].split()
        UNIT_DEPS[u] = set(os.path.normpath(x) for x in deps)
        r = run(["gcc"] + WARN_LIB + inc + ["-c", src, "-o", unit_obj(u)], cwd=ROOT)
        return None if r.returncode == 0 else "mutate: cannot compile %s:\n%s" % (src, r.stdout.decode())
    with cf.ThreadPoolExecutor(max_workers=workers) as ex:
        errors = [m for m in ex.map(one, UNITS) if m]
    if errors:
        sys.exit(errors[0])


def prebuild(workers):
    """Test objects and shared objects, compiled once against the real headers."""
    os.makedirs(os.path.join(B, "obj"), exist_ok=True)
    prebuild_units(workers)
    inc = ["-I" + os.path.join(ROOT, d) for d in ("lib/include", "ref", "port/host", "host_tests",
                                                  "examples", "lib/src")]
    jobs = []
    for name, srcs, _, _, _, _ in SUITES:
        for s in srcs:
            jobs.append((os.path.join(ROOT, s), os.path.join(B, "obj", name + ".o"), SUITE_CFLAGS.get(name, [])))
    jobs.append((os.path.join(ROOT, "ref/mdr_ref.c"), os.path.join(B, "obj", "ref.o"), []))
    gen = os.path.join(ROOT, "build/host/gen_tip.c")
    if not os.path.isfile(gen):
        r = run(["make", "--no-print-directory", "build/host/gen_tip.c"], cwd=ROOT)
        if r.returncode != 0:
            sys.exit("mutate: cannot build build/host/gen_tip.c:\n" + r.stdout.decode())
    jobs.append((gen, os.path.join(B, "obj", "gen_tip.o"), []))
    stale = [(src, obj, extra) for src, obj, extra in jobs
             if not (os.path.isfile(obj) and os.path.getmtime(obj) > max(os.path.getmtime(src), newest_header()))]

    def compile_one(job):
        src, obj, extra = job
        return src, run(["gcc"] + TEST_CFLAGS + extra + inc + ["-c", src, "-o", obj])
    with cf.ThreadPoolExecutor(max_workers=workers) as ex:  # (the compilers run side by side)
        compiled = list(ex.map(compile_one, stale))
    for src, r in compiled:
        if r.returncode != 0:
            sys.exit("mutate: cannot compile %s:\n%s" % (src, r.stdout.decode()))


_newest = None


def newest_header():
    global _newest
    if _newest is None:
        t = 0.0
        for d in ("lib/include", "host_tests", "ref", "examples"):
            for f in os.listdir(os.path.join(ROOT, d)):
                if f.endswith(".h"):
                    t = max(t, os.path.getmtime(os.path.join(ROOT, d, f)))
        for fs in KERNEL_FILES.values():
            for f in fs:
                t = max(t, os.path.getmtime(os.path.join(ROOT, f)))
        _newest = t
    return _newest


def expected_trace():
    with open(os.path.join(ROOT, "host_tests", "q31_trace.expected")) as fp:
        return fp.read().strip()


def gen_tip_args():
    """The CLI arguments of make's build/host/gen_tip.c (mk/tests.mk)."""
    with open(os.path.join(ROOT, "mk", "tests.mk")) as fp:
        for line in fp:
            m = re.search(r"/mdr (table .*--name gen_tip)", line)
            if m:
                return m.group(1).split()
    sys.exit("mutate: no gen_tip rule in mk/tests.mk")


def mutant_gen_tip(d, lib):
    """gen_tip.c made by the mutant's CLI, compiled: (object, None), or
    (None, why) where the CLI cannot make it (make would fail there too)."""
    cli = os.path.join(d, "gen_tip_cli")
    r = run(["gcc", os.path.join(B, "obj", "cli.o"), lib, "-lm", "-o", cli])
    if r.returncode != 0:
        return None, "cannot link the CLI"
    try:
        r = subprocess.run([cli] + gen_tip_args(), stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                           timeout=60)
    except subprocess.TimeoutExpired:
        return None, "the CLI's table: time limit"
    if r.returncode != 0:
        return None, "the CLI's table failed"
    src, obj = os.path.join(d, "gen_tip.c"), os.path.join(d, "gen_tip.o")
    with open(src, "wb") as fp:
        fp.write(r.stdout)
    inc = ["-I" + os.path.join(ROOT, x) for x in ("lib/include", "port/host")]
    r = run(["gcc"] + TEST_CFLAGS + inc + ["-c", src, "-o", obj])
    if r.returncode != 0:
        return None, "the CLI's table does not compile"
    return obj, None


def mutant(e, keep):
    """Build and test one mutant; returns (id, verdict, detail, seconds)."""
    t0 = time.time()
    d = os.path.join(B, "m", e["id"])
    shutil.rmtree(d, ignore_errors=True)
    shutil.copytree(os.path.join(ROOT, "lib"), os.path.join(d, "lib"))
    path = os.path.join(d, e["file"])
    text = open(path).read()
    open(path, "w").write(text.replace(e["old"], e["new"], 1))
    inc = ["-I" + os.path.join(d, "lib/include"), "-I" + os.path.join(ROOT, "port/host")]
    objs = []
    for u in UNITS:
        if os.path.normpath(e["file"]) not in UNIT_DEPS[u]:
            objs.append(unit_obj(u))  # (the unit does not include the mutated file)
            continue
        o = os.path.join(d, u + ".o")
        r = run(["gcc"] + WARN_LIB + inc + ["-c", os.path.join(d, "lib/src", u + ".c"), "-o", o])
        if r.returncode != 0:
            return (e["id"], "error", "mutant does not compile: " +
                    r.stdout.decode().strip().splitlines()[0], time.time() - t0)
        objs.append(o)
    lib = os.path.join(d, "libmdr.a")
    run(["ar", "rcs", lib] + objs)
    header_mutant = e["file"].startswith("lib/include")
    verdict, detail = "survived", ""
    for name, srcs, extra, libs, args, limit in suites_for(e.get("module")):
        exe = os.path.join(d, name)
        if header_mutant or e["file"] in KERNEL_FILES.get(name, []):
            # tests see the mutated headers or kernels: compile from source
            tinc = inc + ["-I" + os.path.join(ROOT, x) for x in ("ref", "host_tests", "examples")] + \
                ["-I" + os.path.join(d, "lib/src")]
            ins = [os.path.join(ROOT, s) for s in srcs]
            flags = TEST_CFLAGS + SUITE_CFLAGS.get(name, []) + tinc
        else:
            ins = [os.path.join(B, "obj", name + ".o")]
            flags = []
        if "gen_tip" in extra and not header_mutant:
            # the table test_engine compiles in, made by the mutant's own CLI
            # (as make would: a table bug is in that table too, so the
            # comparison with it cannot be what kills the mutant)
            gobj, why = mutant_gen_tip(d, lib)
            if gobj is None:
                verdict, detail = "killed", "gen_tip (%s)" % why
                break
            extra = [x for x in extra if x != "gen_tip"]
            ins.append(gobj)
        ins += [os.path.join(B, "obj", x + ".o") for x in extra]
        r = run(["gcc"] + flags + ins + [lib] + libs + ["-o", exe])
        if r.returncode != 0:
            return (e["id"], "error", "cannot link %s: %s" % (name, r.stdout.decode()[:200]),
                    time.time() - t0)
        try:
            if name in CLI_SCRIPTS:
                script = CLI_SCRIPTS[name]
                r = run(["bash", os.path.join(ROOT, script), exe], cwd=ROOT, timeout=limit)
                failed = r.returncode != 0
            elif name == "q31_trace":
                r = run([exe], timeout=limit)
                failed = r.returncode != 0 or r.stdout.decode().strip() != expected_trace()
            else:
                r = run([exe] + args, cwd=ROOT, timeout=limit, env=ABORT_ENV)
                failed = r.returncode != 0
        except subprocess.TimeoutExpired:
            verdict, detail = "killed", "%s (time limit %d s)" % (name, limit)
            break
        if failed:
            verdict, detail = "killed", name
            break
    if not keep:
        shutil.rmtree(d, ignore_errors=True)
    return (e["id"], verdict, detail, time.time() - t0)


def main(argv):
    quick, jobs, only, keep = False, 2, None, False
    i = 0
    while i < len(argv):
        a = argv[i]
        if a == "--quick":
            quick = True
        elif a == "--keep":
            keep = True
        elif a == "--jobs" and i + 1 < len(argv):
            i += 1
            jobs = int(argv[i])
        elif a == "--only" and i + 1 < len(argv):
            i += 1
            only = set(argv[i].split(","))
        else:
            print("mutate: unknown argument %s" % a, file=sys.stderr)
            return 2
        i += 1
    entries, errors = parse_list(LIST)
    errors += [m for m in (check_entry(e) for e in entries) if m]
    if errors:
        print("\n".join("mutate: " + x for x in errors), file=sys.stderr)
        return 2
    if only:
        entries = [e for e in entries if e["id"] in only]
    elif quick:
        entries = [e for e in entries if e.get("quick") == "yes"]
    prebuild(jobs)
    lost = [e for e in entries if not any(os.path.normpath(e["file"]) in d for d in UNIT_DEPS.values())]
    if lost:
        print("\n".join("mutate: %s: no unit of the library includes %s" % (e["id"], e["file"]) for e in lost),
              file=sys.stderr)
        return 2
    t0 = time.time()
    results = {}
    with cf.ThreadPoolExecutor(max_workers=jobs) as ex:
        futs = {ex.submit(mutant, e, keep): e for e in entries}
        for f in cf.as_completed(futs):
            e = futs[f]
            mid, verdict, detail, secs = f.result()
            results[mid] = (verdict, detail, secs)
            eq = "equivalent" in e
            tag = verdict
            if eq:
                tag = "equivalent" if verdict == "survived" else "NOT EQUIVALENT (" + verdict + ")"
            elif verdict == "survived":
                tag = "SURVIVED"
            print("%-28s %-10s %-34s %5.1f s  %s" % (mid, e["module"], tag + (": " + detail
                                                                            if detail else ""),
                                                     secs, e.get("why", "")[:60]), flush=True)
    killed = sum(1 for e in entries if results[e["id"]][0] == "killed" and "equivalent" not in e)
    surv = [e for e in entries if results[e["id"]][0] == "survived" and "equivalent" not in e]
    equiv = [e for e in entries if "equivalent" in e and results[e["id"]][0] == "survived"]
    bad_equiv = [e for e in entries if "equivalent" in e and results[e["id"]][0] != "survived"]
    errs = [e for e in entries if results[e["id"]][0] == "error"]
    mods = sorted(set(e["module"] for e in entries))
    print("mutate%s: %d mutations over %d modules (%s): %d killed, %d equivalent, %d survived%s "
          "(%.0f s, %d jobs)" % (" --quick" if quick else "", len(entries), len(mods),
                                 " ".join(mods), killed, len(equiv), len(surv),
                                 ", %d list errors" % (len(errs) + len(bad_equiv))
                                 if errs or bad_equiv else "", time.time() - t0, jobs))
    for e in surv:
        print("  survived: %s (mutations.txt:%d, %s): %s -> %s" % (
            e["id"], e["line"], e["file"], e["old"].strip(), e["new"].strip()))
    for e in errs + bad_equiv:
        print("  list error: %s: %s" % (e["id"], results[e["id"]][1] or results[e["id"]][0]))
    return 1 if surv or errs or bad_equiv else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
