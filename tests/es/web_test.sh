#!/usr/bin/env bash
# web_test.sh [PAGE_DIR] - the browser test: headless Chromium on SwiftShader
# (WebGL2 through ANGLE) opens PAGE_DIR/es_test.html (default build/web) from disk, which runs
# every technique, compares each mask with the desktop build's and reports
# in its title; --dump-dom prints the page once it has run (the module is
# compiled synchronously, so the run ends before the load event).
# Prints the page's log and "web_browser: N passed, M failed"; exit 1 when
# anything failed or the page did not finish.
set -uo pipefail
dir=$(cd "${1:-${BUILD:-build}/web}" && pwd)
browser=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$browser" ]; then
    echo "web_browser: chromium not found (scripts/deps.sh web)"; echo "web_browser: 0 passed, 1 failed"; exit 1
fi
profile=$(mktemp -d "${TMPDIR:-/tmp}/sk_chromium.XXXXXX") || exit 1
trap 'rm -rf "$profile"' EXIT
# --no-sandbox: CI runs as root, where Chromium's sandbox refuses to start
out=$(timeout 150 "$browser" --headless=new --no-sandbox --use-angle=swiftshader --enable-unsafe-swiftshader \
      --use-gl=angle --disable-gpu-shader-disk-cache --user-data-dir="$profile" \
      --virtual-time-budget=60000 --dump-dom "file://$dir/es_test.html" 2>/dev/null)
title=$(printf '%s' "$out" | sed -n 's:.*<title>\(.*\)</title>.*:\1:p' | head -n 1)
printf '%s\n' "$out" | sed -n '/<pre id="log">/,/<\/pre>/p' | sed 's/<[^>]*>//g' | sed '/^$/d'
case "$title" in
    "ESWEB PASS "*|"ESWEB FAIL "*)
        set -- $title
        echo "web_browser: $3 passed, $5 failed"
        [ "$5" = 0 ] ;;
    *)
        echo "web_browser: the page did not finish (title: '${title}')"
        echo "web_browser: 0 passed, 1 failed"; exit 1 ;;
esac
