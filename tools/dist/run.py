#!/usr/bin/env python3
"""make dist / make test-dist: runs each channel script tools/dist/CHANNEL.sh
(`build DISTDIR` or `test DISTDIR`; the interface is described in
tools/dist/lib/common.sh) one after the other, keeps each one's output in
DISTDIR/logs/CHANNEL-STEP.log and prints a summary table: channel, artifact,
size, result.  After `test`, the smoke test's value y(4.2) (the "smoke:"
lines) must be the same double on every channel that prints one.

    tools/dist/run.py build|test|all DISTDIR [CHANNEL ...]   (default: every channel)

`all` (make test-dist) builds each channel, then tests the ones that built.

Exit status 0 when no channel failed (77, "cannot run here", is not a failure
but is shown as "skipped").
"""
import glob
import os
import re
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SKIP = 77
TIMEOUT = 900  # seconds per channel and step


def channels():
    return sorted(os.path.basename(p)[:-3] for p in glob.glob(os.path.join(HERE, "*.sh")))


def human(n):
    for unit in ("B", "KB", "MB"):
        if n < 1024 or unit == "MB":
            return "%d %s" % (n, unit) if unit == "B" else "%.1f %s" % (n, unit)
        n /= 1024.0


def run_channel(step, dist, name):
    log = os.path.join(dist, "logs", "%s-%s.log" % (name, step))
    t0 = time.time()
    try:
        script = os.path.join(HERE, name + ".sh")
        # by its own #! line when executable (a bash script), else sh
        cmd = [script] if os.access(script, os.X_OK) else ["sh", script]
        r = subprocess.run(cmd + [step, dist],
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=TIMEOUT)
        out, rc = r.stdout.decode("utf-8", "replace"), r.returncode
    except subprocess.TimeoutExpired as e:
        out, rc = (e.stdout or b"").decode("utf-8", "replace") + "\ntimeout\n", 124
    with open(log, "w", encoding="utf-8") as fh:
        fh.write(out)
    return out, rc, time.time() - t0, log


def main():
    if len(sys.argv) < 3 or sys.argv[1] not in ("build", "test", "all"):
        sys.exit(__doc__)
    step, dist = sys.argv[1], os.path.abspath(sys.argv[2])
    names = sys.argv[3:] or channels()
    unknown = [n for n in names if n not in channels()]
    if unknown:
        sys.exit("no channel script tools/dist/%s.sh" % ", ".join(unknown))
    os.makedirs(os.path.join(dist, "logs"), exist_ok=True)
    t0 = time.time()
    if step == "all":
        build_failed = steps("build", dist, names)
        test_failed = steps("test", dist, [n for n in names if n not in build_failed])
        ok = not build_failed and not test_failed
    else:
        ok = not steps(step, dist, names)
    print("%s: %.0f s" % (step, time.time() - t0))
    sys.exit(0 if ok else 1)


def steps(step, dist, names):
    """Runs STEP of each channel; prints the summary; returns the failed channels."""
    rows, failed, values, all_notes = [], [], {}, []
    for name in names:
        print("== %s %s" % (step, name), flush=True)
        out, rc, secs, log = run_channel(step, dist, name)
        if rc == 0:
            result = "ok"
        elif rc == SKIP:
            result = "skipped"
        else:
            result = "FAILED (exit %d)" % rc
            failed.append(name)
            print("\n".join(out.splitlines()[-40:]))
            print("(full log: %s)" % log)
        arts = re.findall(r"^artifact: (\S+) (\d+)", out, re.M)
        if step == "build":
            with open(os.path.join(dist, "logs", name + ".artifacts"), "w") as fh:
                fh.writelines("%s %s\n" % a for a in arts)
        else:
            path = os.path.join(dist, "logs", name + ".artifacts")
            if not arts and os.path.exists(path):
                arts = [tuple(line.split()) for line in open(path) if line.strip()]
        notes = re.findall(r"^note: (.*)$", out, re.M)
        for m in re.finditer(r"^smoke: y\(4\.2\) = (\S+) certified (\d)", out, re.M):
            try:
                values.setdefault(float(m.group(1)), []).append(name)
            except ValueError:
                values.setdefault(m.group(1), []).append(name)
        result += " (%.0f s)" % secs
        if not arts:
            rows.append((name, "-", "-", result))
        for i, (path, size) in enumerate(arts):
            rows.append((name if i == 0 else "", path, human(int(size)), result if i == 0 else ""))
        all_notes.extend("%s: %s" % (name, n) for n in notes)
    if step == "test" and len(values) > 1:
        failed.append("smoke values differ")
        rows.append(("all", "smoke y(4.2) differs: %s" % values, "", "FAILED"))
    elif step == "test" and values:
        (v, who), = values.items()
        rows.append(("all", "smoke y(4.2) = %r on %d runs (%s)" % (v, len(who),
                     ", ".join(sorted(set(who)))), "", "same"))
    w = [max(len(r[i]) for r in rows + [("channel", "artifact", "size", "result")])
         for i in range(4)]
    print("\nmake %s: summary (logs in %s)" % ("dist" if step == "build" else "test-dist",
                                              os.path.join(dist, "logs")))
    for r in [("channel", "artifact", "size", "result")] + rows:
        print("  ".join(c.ljust(w[i]) if i < 3 else c for i, c in enumerate(r)).rstrip())
    for note in all_notes:
        print("note: " + note)
    if failed:
        print("FAILED: %s" % ", ".join(failed))
    return failed


if __name__ == "__main__":
    main()
