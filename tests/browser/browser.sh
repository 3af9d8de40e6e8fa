# Sourced by the browser tests (tests/browser/web_map_*.sh): finds headless
# Chromium, or skips the test (exit 77, ctest's SKIP_RETURN_CODE), and gives
# `browse ARGS...`, Chromium with the network shut off (every host resolves
# to nothing, the proxy is a closed port), its messages in $out/chromium.log.
chromium="$(command -v chromium || command -v chromium-browser || true)"
if [ -z "$chromium" ]; then
  echo "SKIP: Chromium is absent (apt-get install chromium; scripts/setup.sh installs it)"
  exit 77
fi
browse() {
  "$chromium" --headless=new --no-sandbox --disable-gpu --disable-dev-shm-usage --hide-scrollbars --no-first-run \
    --host-resolver-rules="MAP * ~NOTFOUND" --proxy-server="127.0.0.1:9" \
    --window-size=1400,900 --virtual-time-budget=20000 "$@" 2> "$out/chromium.log"
}
