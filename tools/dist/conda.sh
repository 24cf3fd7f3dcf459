#!/bin/sh
# conda channel: the recipe packaging/conda/ (libtrigspline and the Python
# package trigspline).  It cannot be built here: conda-build is not
# installed and the conda-forge channels (compilers, python, numpy) are not
# reachable, and no other registry stands in for them.  So:
#   build: the recipe is checked -- its Jinja renders and its YAML parses,
#          the version is CMakeLists.txt's, the Python output's host and run
#          requirements are pyproject.toml's build and runtime requirements,
#          the licence agrees, the scripts pass `bash -n`, the files its
#          tests use exist -- and packed as DISTDIR/trigspline-VERSION-conda-recipe.tar.gz
#          (what goes to conda-forge's staged-recipes).  With conda-build on
#          PATH it builds the packages instead.
#   test:  with packages built, nothing is left to do here (conda-build ran
#          the recipe's tests); without, exit 77 (not possible here).
. "$(dirname "$0")/lib/common.sh"
ts_setup conda "$2"
RECIPE=$TS_ROOT/packaging/conda
tarball=$TS_DIST/trigspline-$TS_VERSION-conda-recipe.tar.gz
case $1 in
build)
    ts_need /usr/lib/python3/dist-packages/yaml/__init__.py:python3-yaml \
        /usr/lib/python3/dist-packages/jinja2/__init__.py:python3-jinja2
    /usr/bin/python3 - "$RECIPE" "$TS_ROOT" "$TS_VERSION" <<'PYEOF' || exit 1
import os, re, sys, tomllib
import jinja2, yaml
recipe, root, version = sys.argv[1:]
bad = []
env = jinja2.Environment(undefined=jinja2.StrictUndefined)
text = open(os.path.join(recipe, "meta.yaml")).read()
stub = dict(compiler=lambda lang: "%s_compiler_stub" % lang, stdlib=lambda lang: "sysroot_stub",
            pin_subpackage=lambda name, **kw: "%s pin" % name)
meta = yaml.safe_load(env.from_string(text).render(**stub))
if meta["package"]["version"] != version:
    bad.append("version %s, CMakeLists.txt says %s" % (meta["package"]["version"], version))
src = os.path.normpath(os.path.join(recipe, meta["source"]["path"]))
if not os.path.exists(os.path.join(src, "CMakeLists.txt")):
    bad.append("source path %s is not the repository" % src)
outs = {o["name"]: o for o in meta["outputs"]}
if sorted(outs) != ["libtrigspline", "trigspline"]:
    bad.append("outputs %s" % sorted(outs))
names = lambda reqs: {re.split(r"[ <>=]", r)[0] for r in reqs}
py = tomllib.load(open(os.path.join(root, "bindings", "python", "pyproject.toml"), "rb"))
host = names(outs["trigspline"]["requirements"]["host"])
need = {re.split(r"[ <>=]", r)[0] for r in py["build-system"]["requires"]} | {"python", "pip"}
if not need <= host:
    bad.append("host requirements lack %s (pyproject.toml build-system.requires)" % (need - host))
run = outs["trigspline"]["requirements"]["run"]
want = ["python " + py["project"]["requires-python"]] + [d.replace(">=", " >=", 1) if " " not in d else d
                                                         for d in py["project"]["dependencies"]]
if sorted(run) != sorted(want):
    bad.append("run requirements %s, pyproject.toml says %s" % (run, want))
if meta["about"]["license"] != py["project"]["license"]["text"]:
    bad.append("licence %s vs %s" % (meta["about"]["license"], py["project"]["license"]["text"]))
if not os.path.exists(os.path.join(src, meta["about"]["license_file"])):
    bad.append("license_file missing")
for o in outs.values():
    script = os.path.join(recipe, o["script"])
    if not os.access(script, os.X_OK):
        bad.append("%s missing or not executable" % o["script"])
    for f in o.get("test", {}).get("source_files", []):
        if not os.path.exists(os.path.join(src, f)):
            bad.append("test file %s missing" % f)
for b in bad:
    print("recipe: " + b)
print("recipe: %s, version %s, outputs %s: %s" % (os.path.relpath(recipe, root), version,
      ", ".join(sorted(outs)), "consistent" if not bad else "INCONSISTENT"))
sys.exit(1 if bad else 0)
PYEOF
    for s in "$RECIPE"/*.sh; do bash -n "$s" || exit 1; done
    if command -v conda-build >/dev/null 2>&1; then
        conda-build "$RECIPE" --output-folder "$TS_DIST/conda" || exit 1
        for f in "$TS_DIST"/conda/*/*.conda "$TS_DIST"/conda/*/*.tar.bz2; do
            [ -f "$f" ] && ts_artifact "$f"
        done
        exit 0
    fi
    tar -C "$TS_ROOT/packaging" --owner=0 --group=0 --sort=name -czf "$tarball" conda
    ts_artifact "$tarball"
    echo "note: recipe checked, not built: conda-build is not installed and conda-forge's channels are not reachable here"
    ;;
test)
    if ls "$TS_DIST"/conda/*/*.conda "$TS_DIST"/conda/*/*.tar.bz2 >/dev/null 2>&1; then
        echo "conda-build ran the recipe's tests (the smoke test) when it built the packages"
        exit 0
    fi
    echo "note: no conda package to install (the recipe is not built here)"
    exit 77
    ;;
*) echo "usage: $0 build|test DISTDIR" >&2; exit 2 ;;
esac
