#!/usr/bin/env bash
# Renders `ogive report` of one scene with headless Chromium (Debian's chromium-headless-shell or
# chromium) to PNG and PDF, and checks that the page loads without a console message or a reference to another file and that the rendered
# DOM shows the numbers that ogive thrust prints. Usage: bash .ci/check_report.sh BUILD_DIR [OUT_DIR]
set -euo pipefail
build=${1:?usage: check_report.sh BUILD_DIR [OUT_DIR]}
out=$(realpath -m "${2:-$(mktemp -d)}")
mkdir -p "$out"
browser=$(command -v chromium-headless-shell || command -v chromium || true)
[[ -n "$browser" ]] || { echo "check_report: no chromium (bash .ci/install_deps.sh --charts)"; exit 1; }
scene=(--span 8 --eccentricity 0.5 --thickness-ratio 0.1 --density 2000 --fill-density 2000 --fill-height-ratio 0.924
       --point-load 50000 --point-load-at 0.25)
"$build/ogive" report "${scene[@]}" --output "$out/report.html"
flags=(--headless --no-sandbox --disable-gpu --allow-file-access-from-files --enable-logging=stderr --v=0)
"$browser" "${flags[@]}" --window-size=1000,2400 --screenshot="$out/report.png" "file://$out/report.html" 2>"$out/png.log"
"$browser" "${flags[@]}" --no-pdf-header-footer --print-to-pdf="$out/report.pdf" "file://$out/report.html" 2>"$out/pdf.log"
"$browser" "${flags[@]}" --dump-dom "file://$out/report.html" >"$out/dom.html" 2>"$out/dom.log"
status=0
for f in report.png report.pdf; do [[ -s "$out/$f" ]] || { echo "check_report: $f not written"; status=1; }; done
# The page runs no script, so any console message (an error, a resource that failed) is a fault.
if grep -qh ":CONSOLE" "$out"/*.log; then echo "check_report: console messages:"; grep -h ":CONSOLE" "$out"/*.log; status=1; fi
if grep -qE '(src|href)=' "$out/dom.html"; then echo "check_report: the page refers to another file"; status=1; fi
# The numbers the page shows, as ogive thrust prints them (H and V in kN/m, 4 significant digits).
H=$("$build/ogive" thrust "${scene[@]}" --columns H | tail -1 | cut -d, -f2)  # the row is scene,H
[[ $H =~ ^[0-9][0-9.e+-]*$ ]] || { echo "check_report: ogive thrust printed no H ('$H')"; exit 1; }
shown=$(awk -v h="$H" 'BEGIN { printf "%.4g kN/m", h / 1000 }')
grep -q "$shown" "$out/dom.html" || { echo "check_report: the rendered page does not show H = $shown"; status=1; }
for id in verdict drawing reactions thrusts safety collapse spreading geometry inputs assumptions; do
  grep -q "<section id=\"$id\"" "$out/dom.html" || { echo "check_report: no section $id"; status=1; }
done
# The verdict first: the first section of the rendered page, in words.
first=$(grep -o '<section id="[a-z]*"' "$out/dom.html" | head -1)
[[ $first == '<section id="verdict"' ]] || { echo "check_report: the first section is $first, not the verdict"; status=1; }
grep -qE '<p class="word">(PASS|FAIL|NOT ASSESSED)</p>' "$out/dom.html" || { echo "check_report: no verdict in words"; status=1; }
# An arch that fails: the 12 m segmental bridge arch, 0.3 m ring, 100 kN/m at 3 m. The rendered page's
# first words after its title are the verdict FAIL, governed by the load factor, as ogive assess says.
"$build/ogive" report --curve segmental --span 12 --rise 3 --thickness 0.3 --fill-density 2000 --fill-height 3.8 \
  --point-load 100kN --point-load-x 3 --output "$out/bridge.html" >/dev/null
"$browser" "${flags[@]}" --dump-dom "file://$out/bridge.html" >"$out/bridge-dom.html" 2>"$out/bridge-dom.log"
verdict=$("$build/ogive" assess --curve segmental --span 12 --rise 3 --thickness 0.3 --fill-density 2000 \
  --fill-height 3.8 --point-load 100kN --point-load-x 3 --columns verdict,governing | tail -1)
[[ $verdict == "1,fail,load_factor" ]] || { echo "check_report: assess says '$verdict' of the bridge"; status=1; }
grep -q '<section id="verdict" class="fail"><h2>Verdict</h2>' "$out/bridge-dom.html" &&
  grep -q '<p class="word">FAIL</p>' "$out/bridge-dom.html" &&
  grep -q 'Governed by the collapse load factor' "$out/bridge-dom.html" ||
  { echo "check_report: the bridge's rendered page does not open with FAIL governed by the load factor"; status=1; }
[[ $status -eq 0 ]] && echo "check_report: rendered $out/report.png and $out/report.pdf; H = $shown shown; the bridge's page opens with FAIL"
exit $status
