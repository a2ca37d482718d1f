#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The recipes in packaging/ that cannot run here (Spack, EasyBuild,
# Apptainer; docs/INSTALL.md): each parses (Python for the Spack recipe and
# the easyconfig), names the version of CMakeLists.txt's project(), and
# carries what its format requires: the Spack class derives from
# CMakePackage with cmake_args; the easyconfig sets EasyBuild's mandatory
# parameters with the CMakeMake easyblock; the Apptainer file has a
# bootstrap header and a %test that runs the demo.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
version=$(sed -n 's/^project(gridfree VERSION \([0-9.]*\).*/\1/p' "$root/CMakeLists.txt")
python3 - "$root" "$version" <<'PY'
import ast, sys
root, version = sys.argv[1], sys.argv[2]
errors = []

spack = root + "/packaging/spack/gridfree/package.py"
tree = ast.parse(open(spack).read(), spack)
classes = [n for n in tree.body if isinstance(n, ast.ClassDef)]
if [c.name for c in classes] != ["Gridfree"]:
    errors.append(f"{spack}: one class Gridfree expected, found {[c.name for c in classes]}")
else:
    cls = classes[0]
    if [b.id for b in cls.bases if isinstance(b, ast.Name)] != ["CMakePackage"]:
        errors.append(f"{spack}: Gridfree must derive from CMakePackage")
    if "cmake_args" not in [f.name for f in cls.body if isinstance(f, ast.FunctionDef)]:
        errors.append(f"{spack}: no cmake_args")
    versions = [c.args[0].value for c in ast.walk(cls)
                if isinstance(c, ast.Call) and getattr(c.func, "id", "") == "version" and c.args]
    if version not in versions:
        errors.append(f"{spack}: no version('{version}') (has {versions})")

eb = root + f"/packaging/easybuild/gridfree-{version}-GCC-13.3.0.eb"
try:
    params = {}
    for n in ast.parse(open(eb).read(), eb).body:
        if isinstance(n, ast.Assign) and isinstance(n.targets[0], ast.Name):
            params[n.targets[0].id] = ast.literal_eval(n.value)
    for key in ("easyblock", "name", "version", "homepage", "description", "toolchain"):
        if key not in params:
            errors.append(f"{eb}: mandatory parameter {key} missing")
    if params.get("easyblock") != "CMakeMake":
        errors.append(f"{eb}: easyblock is not CMakeMake")
    if params.get("version") != version:
        errors.append(f"{eb}: version {params.get('version')} is not {version}")
except (OSError, SyntaxError, ValueError) as e:
    errors.append(f"{eb}: {e}")

apptainer = root + "/packaging/apptainer/gridfree.def"
text = open(apptainer).read()
if "\nBootstrap: " not in "\n" + text:
    errors.append(f"{apptainer}: no Bootstrap header")
sections = [l.split()[0] for l in text.splitlines() if l.startswith("%")]
for s in ("%post", "%test", "%runscript"):
    if s not in sections:
        errors.append(f"{apptainer}: no {s} section")
test = text.split("\n%test", 1)[-1].split("\n%", 1)[0]
if "studies/quickstart.json" not in test:
    errors.append(f"{apptainer}: %test does not run the demo study")

for e in errors:
    print("FAIL:", e)
sys.exit(1 if errors else 0)
PY
echo "packaging recipes: ok"
