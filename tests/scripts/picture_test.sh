#!/usr/bin/env bash
# Issue 39, item 2: pictures of any scene. A room in its own units without a camera is framed (its
# picture is not dark, no warning); the same room with a camera that looks away warns that the picture
# is dark, on stderr and in report.json's image_warning. Seconds.
set -euo pipefail
sim="$1"
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
cat > "$work/room.scene" <<'SCENE'
material white reflectance 0.7 0.7 0.7
material lamp reflectance 0.5 0.5 0.5 emission 10 10 10
quad floor   white  1 0 0   0 0 0   0 0 1   1 0 1
quad ceiling white  1 1 0   1 1 1   0 1 1   0 1 0
quad back    white  1 0 1   0 0 1   0 1 1   1 1 1
quad lamp    lamp   0.6 0.99 0.4   0.6 0.99 0.6   0.4 0.99 0.6   0.4 0.99 0.4
SCENE
"$sim" run --scene "$work/room.scene" --patch-levels 1 --steps 20 --image-size 64 --quiet --out "$work/framed" 2> "$work/framed.err" > /dev/null
! grep -q "picture is dark" "$work/framed.err" || fail "the framed room's picture is dark: $(cat "$work/framed.err")"
python3 -c 'import json, sys; assert json.load(open(sys.argv[1]))["image_warning"] is None' "$work/framed/report.json" ||
  fail "image_warning set for the framed room"
# The Cornell camera (the default before framing) in this unit room sees nothing.
cp "$work/room.scene" "$work/away.scene"
echo "camera 278 273 -800  278 273 0  0 1 0  39.3" >> "$work/away.scene"
"$sim" run --scene "$work/away.scene" --patch-levels 1 --steps 20 --image-size 64 --quiet --out "$work/away" 2> "$work/away.err" > /dev/null
grep -q "warning: the picture is dark: 100.0% of its pixels are black" "$work/away.err" || fail "no dark-picture warning: $(cat "$work/away.err")"
python3 -c 'import json, sys; assert "dark" in json.load(open(sys.argv[1]))["image_warning"]' "$work/away/report.json" ||
  fail "report.json has no image_warning"
# The Cornell Box's picture is unchanged by the rule (it has its camera) and not dark.
"$sim" run --steps 20 --patch-levels 1 --image-size 64 --quiet --out "$work/box" 2> "$work/box.err" > /dev/null
! grep -q "picture is dark" "$work/box.err" || fail "the box's picture is dark"
echo "PASS: a room without a camera is framed; a camera that sees nothing is warned about"
