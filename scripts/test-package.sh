#!/usr/bin/env bash
# The Debian package, built and installed without a container: cpack builds build/softtune_<version>_<arch>.deb
# from the Release build (scripts/build.sh; cmake/Package.cmake says what it holds), dpkg-deb unpacks it into
# a scratch root, and the installed tree is run as a user would: `softtune --version`, then `softtune serve`
# with the systemd unit's own --web and --presets folders (moved under the scratch root) answering
# GET /api/v1/health with the same version, the page, and the preset list.
set -euo pipefail
cd "$(dirname "$0")/.."
(cd build && cpack -G DEB >/dev/null)
deb=$(ls -t build/softtune_*.deb | head -n1)
root=$(mktemp -d)
server=""
cleanup() {
  [[ -n $server ]] && kill "$server" 2>/dev/null && wait "$server" 2>/dev/null
  rm -rf "$root"
}
trap cleanup EXIT
dpkg-deb -x "$deb" "$root"
echo "package: $deb ($(du -k "$deb" | cut -f1) KiB): $(dpkg-deb -f "$deb" Package Version Depends | tr '\n' ' ')"

for f in usr/bin/softtune usr/bin/softtune-raster usr/share/softtune/web/index.html usr/share/softtune/presets \
  usr/share/doc/softtune/README.md usr/share/doc/softtune/docs/testing.md usr/lib/systemd/system/softtune.service; do
  [[ -e $root/$f ]] || { echo "package: /$f missing"; exit 1; }
done
version=$("$root/usr/bin/softtune" --version)
[[ $version =~ ^softtune\ [0-9]+\.[0-9]+\.[0-9]+$ ]] || { echo "package: --version printed \"$version\""; exit 1; }

# The unit's ExecStart, with the installed paths moved under the scratch root and a free port.
exec_start=$(sed -n 's/^ExecStart=//p' "$root/usr/lib/systemd/system/softtune.service")
read -r -a argv <<<"$exec_start"
for i in "${!argv[@]}"; do
  [[ ${argv[$i]} == /usr/* ]] && argv[$i]=$root${argv[$i]}
  [[ ${argv[$i]} == --port ]] && argv[$((i + 1))]=0
done
log=$root/serve.log
"${argv[@]}" >"$log" 2>&1 &
server=$!
port=""
for _ in $(seq 100); do
  port=$(sed -n 's|.*serving http://127.0.0.1:\([0-9]*\)/.*|\1|p' "$log")
  [[ -n $port ]] && break
  sleep 0.1
done
[[ -n $port ]] || { echo "package: the installed softtune serve did not start:"; cat "$log"; exit 1; }
python3 - "$port" "${version#softtune }" <<'PY'
import json, sys, urllib.request
port, version = sys.argv[1], sys.argv[2]
base = f"http://127.0.0.1:{port}"
health = json.load(urllib.request.urlopen(base + "/api/v1/health", timeout=10))
assert health["status"] == "ok" and health["version"] == version, health
page = urllib.request.urlopen(base + "/", timeout=10).read().decode()
assert "<html" in page.lower(), page[:200]
presets = json.load(urllib.request.urlopen(base + "/api/v1/presets", timeout=10))
assert presets, presets
print(f"package: installed softtune {version} serves health, the page and {len(presets.get('presets', presets))} presets")
PY
