#!/usr/bin/env bash
# Installs the .deb on a clean Debian (a minbase bookworm chroot made by debootstrap), then runs
# one study from the installed program and one from the installed Python module. Not part of the
# suite: it downloads the base system and camopt's runtime dependencies (about 150 packages).
# Needs root, debootstrap and network access. Usage: test_deb_in_chroot.sh BUILD [ROOT]
set -euo pipefail
build=$(cd "$1" && pwd)
root=${2:-/tmp/camopt-deb-chroot}
source=$(cd "$(dirname "$0")/.." && pwd)
deb=$(ls "$build"/camopt_*_amd64.deb | head -1)
[ -f "$deb" ] || { echo "no .deb in $build: run (cd $build && cpack) first"; exit 1; }
if [ ! -x "$root/bin/bash" ]; then
  debootstrap --variant=minbase bookworm "$root" http://deb.debian.org/debian
fi
cp "$deb" "$root/tmp/camopt.deb"
cp "$source/studies/examples/lcr_ii.json" "$root/tmp/"
mountpoint -q "$root/proc" || mount -t proc proc "$root/proc"
trap 'umount "$root/proc" 2>/dev/null || true' EXIT
chroot "$root" /bin/bash -c "apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq /tmp/camopt.deb >/dev/null"
chroot "$root" /bin/bash -c "cd /tmp && camopt --version && camopt run lcr_ii.json --out out_deb --quiet && test -f out_deb/report.html"
chroot "$root" /usr/bin/python3 -c "import camopt; r = camopt.run('/tmp/lcr_ii.json'); assert r['speed_ratio'] == -90; print('python module: speed ratio', r['speed_ratio'])"
echo "the .deb installs on a clean bookworm and runs from the program and from Python"
