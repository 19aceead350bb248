#!/usr/bin/env bash
# docs/adding-a-technique.md, followed as a new user would (issue 13): this
# build installed into a fresh prefix (the page's step 0), then every block
# of the page in order from an empty folder: a ```LANG file=PATH block is
# written to PATH, a ```sh block is run, and a ```text output block must
# appear in what the sh block before it printed.
# PART 1 (sdk.tutorial, in ./test.sh) runs the page up to its part 2;
# PART 2 (sdk.tutorial_part2, label long: four more builds of a user's
# project) runs part 2 from where part 1 leaves the reader, beside a `sheet`
# folder.
# Usage: tutorial_test.sh SOURCE_DIR BUILD_DIR CXX_COMPILER PART
set -euo pipefail
source "$(dirname "$0")/lib.sh"
part="${4:?PART (1 or 2)}"
sdk_setup "$@"

export SHADERTWIN_PREFIX="$work/prefix"
# The page's cmake commands take the compiler the libraries were built with.
export CXX="$cxx"
mkdir "$work/home"
python3 - "$src/docs/adding-a-technique.md" "$work/home" "$part" <<'PY'
import os, re, subprocess, sys

page, home, part = sys.argv[1], sys.argv[2], sys.argv[3]
text = open(page).read()
part2 = text.index("\n## Tutorial, part 2")
if part == "1":
    text = text[:part2]
else:
    text = text[part2:text.index("\n## Reference")]
    os.makedirs(os.path.join(home, "sheet"))  # where part 1 leaves the reader
blocks = re.findall(r"^```([^\n]*)\n(.*?)^```$", text, re.S | re.M)
cwd = home if part == "1" else os.path.join(home, "sheet")
last_output = None
ran = files = checked = 0
for info, body in blocks:
    words = info.split()
    lang = words[0] if words else ""
    target = next((w[5:] for w in words if w.startswith("file=")), None)
    if target:
        path = os.path.join(cwd, target)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as f:
            f.write(body)
        files += 1
    elif lang == "sh":
        # One shell per block, started where the last one ended (a `cd`
        # carries over, as in the reader's terminal).
        script = "set -euo pipefail\n" + body + '\npwd >"$ST_PWD_FILE"\n'
        pwd_file = os.path.join(home, ".pwd")
        r = subprocess.run(["bash", "-c", script], cwd=cwd, capture_output=True, text=True,
                           env=dict(os.environ, ST_PWD_FILE=pwd_file))
        print("$ " + body.strip().replace("\n", "\n$ "))
        print(r.stdout + r.stderr, end="")
        if r.returncode != 0:
            sys.exit(f"FAIL: the block above exited {r.returncode}")
        cwd = open(pwd_file).read().strip()
        last_output = r.stdout
        ran += 1
    elif lang == "text" and "output" in words:
        if last_output is None:
            sys.exit("FAIL: an output block before any command")
        for line in body.splitlines():
            if line.strip() and line.rstrip() not in [l.rstrip() for l in last_output.splitlines()]:
                sys.exit(f"FAIL: the page shows\n  {line}\nbut the command printed\n{last_output}")
        checked += 1
if ran < 4 or files < 6 or checked < 1:
    sys.exit(f"FAIL: the page has {ran} commands, {files} files, {checked} outputs: fewer than the tutorial needs")
print(f"ok   docs/adding-a-technique.md, part {part}: {files} files written, {ran} command blocks run, {checked} outputs as shown")
PY
