#!/usr/bin/env bash
# tests/integration/examples_window.sh - every example in a real GLFW window.
#
# Starts Xvfb on a free display (-displayfd: the server picks the number),
# runs each example and each --technique variant that `make demo` renders
# in a 1280x720 window for 3 frames with --out (common.c then steps the
# clock at 60 Hz like --headless and saves the last frame's back buffer
# with glReadPixels before the swap), renders the same example --headless
# for 3 frames on OSMesa, and compares the two PNGs with image_compare: at
# most 0.5% of the pixels may differ (any channel). Both sides are Mesa's
# llvmpipe (GLX on Xvfb, and OSMesa), so the images agree almost exactly:
# measured 4 to 31 differing pixels of 921600 per pair (at most 0.0034%;
# the figures are printed per pair). Images, and -diff.png maps of any
# differing pixels, go to out/tests/integration/examples/.
#
# It can fail: with the window's clock left on glfwGetTime() (the
# save_window test in ex_app_begin_frame removed) the moving sun, camera
# and lamp put 01, 02, 02 --show-cascades and both 05 variants at 2.3% to
# 89% of differing pixels: 5 failed checks. A run that writes no PNG
# fails its pair too.
#
# Run from the repository root after `make` has built build/examples/ and
# build/integration/bin/image_compare (mk/integration.mk installs this
# script as build/integration/examples_window). Ends with the summary line
# "examples_window: N passed, M failed".
set -uo pipefail

BUILD=${BUILD:-build}
EX=$BUILD/examples
CMP=$BUILD/integration/bin/image_compare
DIR=out/tests/integration/examples
FRAMES=3
mkdir -p "$DIR"

TMP=$(mktemp -d "${TMPDIR:-/tmp}/sk_xvfb.XXXXXX") || exit 2
XPID=
cleanup() {
    if [ -n "$XPID" ]; then kill "$XPID" 2>/dev/null; wait "$XPID" 2>/dev/null; fi
    rm -rf "$TMP"
}
trap cleanup EXIT
trap 'exit 143' TERM INT HUP   # a timeout still stops Xvfb (through the EXIT trap)

# the screen is larger than the window, so that the window is never clipped
Xvfb -displayfd 3 -screen 0 1600x900x24 -nolisten tcp -noreset 3> "$TMP/display" > "$TMP/xvfb.log" 2>&1 &
XPID=$!
for _ in $(seq 100); do
    [ -s "$TMP/display" ] && break
    kill -0 "$XPID" 2>/dev/null || break
    sleep 0.1
done
if [ ! -s "$TMP/display" ]; then
    echo "FAIL examples_window: Xvfb did not start"
    sed 's/^/    xvfb: /' "$TMP/xvfb.log"
    echo "examples_window: 0 passed, 1 failed"
    exit 1
fi
export DISPLAY=":$(head -n 1 "$TMP/display")"
echo "Xvfb on $DISPLAY"

# name, then the example's arguments
VARIANTS=(
    "01_hard_shadows|01_hard_shadows"
    "02_cascades|02_cascades"
    "02_cascades-show|02_cascades --show-cascades"
    "03_warping-lispsm|03_warping --technique lispsm"
    "03_warping-psm|03_warping --technique psm"
    "03_warping-standard|03_warping --technique standard"
    "04_adaptive-ferko|04_adaptive --technique ferko"
    "04_adaptive-lspsm|04_adaptive --technique lspsm"
    "04_adaptive-rmsm|04_adaptive --technique rmsm"
    "05_point_light-cube|05_point_light --technique cube"
    "05_point_light-vsdct|05_point_light --technique vsdct"
    "06_soft_shadows-pvsm|06_soft_shadows --technique pvsm"
    "06_soft_shadows-pcss|06_soft_shadows --technique pcss"
    "06_soft_shadows-tiles|06_soft_shadows --technique tiles"
    "07_engine_casters|07_engine_casters"
)

pairs=()
for v in "${VARIANTS[@]}"; do
    name=${v%%|*}
    read -r -a args <<< "${v#*|}"
    prog=$EX/${args[0]}
    rm -f "$DIR/$name-window.png" "$DIR/$name-headless.png" "$DIR/$name-window-diff.png"
    # a window on Xvfb (GLX, Mesa's software rasteriser) ...
    if ! "$prog" "${args[@]:1}" --frames "$FRAMES" --out "$DIR/$name-window.png" > "$TMP/run.log" 2>&1; then
        echo "$name: the window run failed:"; sed 's/^/    | /' "$TMP/run.log"
    fi
    # ... and the same frames off-screen on OSMesa
    if ! SK_GL=osmesa "$prog" "${args[@]:1}" --headless --frames "$FRAMES" \
            --out "$DIR/$name-headless.png" > "$TMP/run.log" 2>&1; then
        echo "$name: the headless run failed:"; sed 's/^/    | /' "$TMP/run.log"
    fi
    pairs+=("$name" "$DIR/$name-window.png" "$DIR/$name-headless.png")
done

# (not exec: the EXIT trap stops Xvfb)
"$CMP" --name examples_window --max-pct 0.5 "${pairs[@]}"
