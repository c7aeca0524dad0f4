#!/usr/bin/env bash
# The Debian package, built and checked: cpack in build/ (the folder .ci/test.sh built), lintian, the
# freedesktop validators and man's warnings, then a Debian 12 root that never had the build dependencies
# (debootstrap minbase): the package installed there with apt alone, its programs run (the CLI writes rows,
# --version answers, the GUI draws a window under Xvfb that is not blank, the file types name the app),
# then removed and purged with nothing of it left. Fails on any error; prints how long each part took.
# Needs root (debootstrap, chroot, mount) and Debian's archive; keeps the package and the screenshot
# in build/package/.
set -euo pipefail
cd "$(dirname "$0")/.."

parts=()
part_name=""
part_start=$SECONDS
# Starts the next part, closing the one before with its time.
part() {
  if [ -n "$part_name" ]; then parts+=("$(printf '%4d s  %s' $((SECONDS - part_start)) "$part_name")"); fi
  part_name=$1
  part_start=$SECONDS
  [ -n "$part_name" ] && printf '\n== package: %s\n' "$part_name"
  return 0
}
fail() {
  echo "package: $*" >&2
  exit 1
}

part "tools (lintian, validators, debootstrap)"
./.ci/install-deps.sh packaging

part "build and cpack"
./.ci/build.sh
out=$PWD/build/package
rm -rf "$out" build/particlelab_*.deb
mkdir -p "$out"
(cd build && cpack -G DEB >"$out/cpack.log") || { cat "$out/cpack.log"; fail "cpack failed"; }
debs=(build/particlelab_*_amd64.deb)
[ ${#debs[@]} -eq 1 ] && [ -f "${debs[0]}" ] || fail "cpack made no particlelab_*_amd64.deb"
mv "${debs[0]}" "$out/"
deb=$(ls "$out"/particlelab_*_amd64.deb)
version=$(dpkg-deb --field "$deb" Version)
ls -l "$deb"
dpkg-deb --info "$deb"
dpkg-deb --contents "$deb" | awk '{print $6}'
# One version everywhere: the package's (the project's), the changelog's and AppStream's newest release.
changelog_version=$(sed -n '1s/^particlelab (\([^)]*\)).*/\1/p' resources/packaging/changelog)
metainfo_version=$(grep -o -m1 '<release version="[^"]*"' resources/desktop/particlelab.metainfo.xml.in |
  cut -d'"' -f2)
[ "$changelog_version" = "$version" ] ||
  fail "resources/packaging/changelog starts at $changelog_version, the package is $version"
[ "$metainfo_version" = "$version" ] ||
  fail "the newest AppStream release is $metainfo_version, the package is $version"
tree=$(mktemp -d)
dpkg-deb --extract "$deb" "$tree"
for path in usr/bin/particlelab usr/bin/particlelab-cli usr/bin/particlelab-bench \
  usr/libexec/particlelab/particlelab-cli-media \
  usr/share/applications/particlelab.desktop usr/share/mime/packages/particlelab.xml \
  usr/share/metainfo/io.github.particlelab.particlelab.metainfo.xml \
  usr/share/icons/hicolor/scalable/apps/particlelab.svg usr/share/icons/hicolor/48x48/apps/particlelab.png \
  usr/share/man/man1/particlelab.1.gz usr/share/man/man1/particlelab-cli.1.gz \
  usr/share/man/man1/particlelab-bench.1.gz usr/share/particlelab/presets/gas/gas-write-up.json \
  usr/share/doc/particlelab/copyright usr/share/doc/particlelab/changelog.gz; do
  [ -f "$tree/$path" ] || fail "the package lacks /$path"
done

part "lintian"
# Every tag of level warning or error fails; the overrides (resources/packaging/lintian-overrides) say
# why each tag they hold is right for this package.
lintian --display-level '>=pedantic' --show-overrides --fail-on error,warning "$deb"

part "validators (desktop-file-validate, appstreamcli, update-mime-database, man)"
desktop-file-validate "$tree/usr/share/applications/particlelab.desktop"
echo "desktop-file-validate: no error"
appstreamcli validate --no-net --explain --pedantic \
  "$tree/usr/share/metainfo/io.github.particlelab.particlelab.metainfo.xml"
# shared-mime-info's own tool reads the type beside the freedesktop types (application/json, its parent)
# and must say nothing.
data_dir=$(mktemp -d)
mime=$data_dir/mime
mkdir -p "$mime/packages"
cp /usr/share/mime/packages/freedesktop.org.xml "$tree/usr/share/mime/packages/particlelab.xml" "$mime/packages/"
mime_messages=$(XDG_DATA_DIRS=$data_dir update-mime-database "$mime" 2>&1)
[ -z "$mime_messages" ] || fail "update-mime-database: $mime_messages"
for type in application/x-particlelab-experiment application/x-particlelab-snapshot; do
  [ -f "$mime/$type.xml" ] || fail "update-mime-database made no $type"
done
echo "update-mime-database: no message; $(cat "$mime/globs2" | grep particlelab | tr '\n' ' ')"
for page in "$tree"/usr/share/man/man1/*.1.gz; do
  warnings=$(MANWIDTH=80 man --warnings -l "$page" 2>&1 >/dev/null)
  [ -z "$warnings" ] || fail "man --warnings -l $(basename "$page"): $warnings"
  echo "man --warnings -l $(basename "$page"): no warning"
done
rm -rf "$tree" "$data_dir"

part "clean root: debootstrap minbase bookworm"
# Debian's archive as this machine's apt reaches it (PARTICLELAB_DEBIAN_MIRROR overrides).
apt_sources=$(cat /etc/apt/sources.list /etc/apt/sources.list.d/*.list /etc/apt/sources.list.d/*.sources \
  2>/dev/null || true)
mirror=${PARTICLELAB_DEBIAN_MIRROR:-$(grep -o 'https\?://[^ ]*/debian/\?\( \|$\)' <<<"$apt_sources" |
  head -n1 | tr -d ' ')}
mirror=${mirror:-http://deb.debian.org/debian}
security=$(grep -o 'https\?://[^ ]*/debian-security/\?\( \|$\)' <<<"$apt_sources" | head -n1 | tr -d ' ')
root=$(mktemp -d /var/tmp/particlelab-root.XXXXXX)
chmod 755 "$root" # the root folder of the system inside: apt's own user reads through it
mounted=()
cleanup() {
  local i
  for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do umount -l "${mounted[i]}" || true; done
  rm -rf --one-file-system "$root"
}
trap cleanup EXIT
trap 'exit 130' INT TERM # through the EXIT trap
echo "mirror $mirror${security:+, security $security}; root $root"
debootstrap --variant=minbase bookworm "$root" "$mirror" >"$out/debootstrap.log" 2>&1 ||
  { tail -n 30 "$out/debootstrap.log"; fail "debootstrap failed"; }
{
  echo "deb $mirror bookworm main"
  echo "deb $mirror bookworm-updates main"
  [ -z "$security" ] || echo "deb $security bookworm-security main"
} >"$root/etc/apt/sources.list"
for fs in proc sys dev dev/pts; do
  case $fs in
    proc) mount -t proc proc "$root/proc" ;;
    sys) mount -t sysfs sysfs "$root/sys" ;;
    *) mount --bind "/$fs" "$root/$fs" ;;
  esac
  mounted+=("$root/$fs")
done
# Runs a command line inside, as root with a bare environment (no display), echoing it first; a
# failure anywhere in a pipe fails it.
in_root() {
  echo "# $*"
  chroot "$root" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LANG=C.UTF-8 \
    DEBIAN_FRONTEND=noninteractive /bin/bash -eo pipefail -c "$*"
}
in_root "dpkg-query -W -f='\${Package}\n' | wc -l"

part "clean root: apt-get install ./$(basename "$deb")"
cp "$deb" "$root/root/"
in_root "apt-get update -q >/dev/null && cd /root && apt-get install -y -q ./$(basename "$deb") |
  grep -E '^Need to get|newly installed|^Setting up particlelab'"
in_root "dpkg-query -W -f='\${Package}\n' | wc -l"

part "clean root: the programs"
in_root "cd /root && particlelab-cli run gas-write-up --steps 200 --out s.csv --quiet && wc -l s.csv && head -n 2 s.csv"
rows=$(($(wc -l <"$root/root/s.csv") - 1))
[ "$rows" -gt 0 ] || fail "particlelab-cli wrote no rows"
# record runs in particlelab-cli-media from libexec, with FFmpeg's libraries from the package's
# dependencies, and needs no display.
in_root "cd /root && particlelab-cli record gas-write-up --out c.gif --seconds 1 --fps 5 --size 160x120 --quiet && ls -l c.gif"
in_root "particlelab --version && particlelab-cli --version && particlelab-bench --version"
[ "$(chroot "$root" particlelab --version)" = "particlelab $version" ] || fail "particlelab --version is not $version"
in_root "particlelab --help | head -n 3"
# No display: one sentence and exit status 2, not an abort.
status=0
in_root "particlelab gas-write-up" || status=$?
[ "$status" -eq 2 ] || fail "particlelab without a display exited with $status, not 2"
# A snapshot (.plsnap) written and continued; an experiment file (.particlelab) run.
in_root "cd /root && particlelab-cli run gas-write-up --steps 20 --snapshot s.plsnap --quiet &&
  particlelab-cli run s.plsnap --steps 20 --out continued.csv --quiet && wc -l continued.csv &&
  cp /usr/share/particlelab/presets/gas/gas-classroom.json classroom.particlelab &&
  particlelab-cli run classroom.particlelab --steps 20 --out classroom.csv --quiet && wc -l classroom.csv"

part "clean root: test tools (Xvfb, xdg-utils)"
in_root "apt-get install -y -q --no-install-recommends xvfb xauth xdg-utils libfile-mimeinfo-perl \
  desktop-file-utils | tail -n 1"

part "clean root: the window under Xvfb, the file types"
# As a file manager opens an experiment: the .desktop file's Exec line with %f the file.
exec_line=$(sed -n 's/^Exec=//p' "$root/usr/share/applications/particlelab.desktop")
[ "$exec_line" = "particlelab %f" ] || fail "Exec=$exec_line does not take %f"
in_root "cd /root && timeout 300 xvfb-run -a -s '-screen 0 1280x800x24' \
  ${exec_line/\%f/classroom.particlelab} --screenshot shot.png --frames 30 && ls -l shot.png"
cp "$root/root/shot.png" "$out/clean-root-screenshot.png"
# Not blank: the window holds many colours, and so does its middle, the particles (the viewport).
pngtopnm "$out/clean-root-screenshot.png" >"$out/shot.ppm"
read -r _ width height < <(head -n 2 "$out/shot.ppm" | tr '\n' ' ' && echo)
colours=$(ppmhist -noheader "$out/shot.ppm" | wc -l)
middle=$(pnmcut -left $((width / 3)) -top $((height / 3)) -width $((width / 3)) -height $((height / 3)) \
  "$out/shot.ppm" | ppmhist -noheader | wc -l)
rm "$out/shot.ppm"
echo "screenshot ${width}x${height}: $colours colours, $middle in its middle third"
[ "$colours" -ge 16 ] && [ "$middle" -ge 4 ] || fail "the window is blank ($colours colours, $middle in the middle)"
in_root "cd /root && xdg-mime query filetype classroom.particlelab && xdg-mime query filetype s.plsnap &&
  xdg-mime query default application/x-particlelab-experiment &&
  xdg-mime query default application/x-particlelab-snapshot"
[ "$(chroot "$root" xdg-mime query filetype /root/classroom.particlelab)" = application/x-particlelab-experiment ] ||
  fail "xdg-mime does not name the experiment type"
[ "$(chroot "$root" xdg-mime query filetype /root/s.plsnap)" = application/x-particlelab-snapshot ] ||
  fail "xdg-mime does not name the snapshot type"
for type in application/x-particlelab-experiment application/x-particlelab-snapshot; do
  [ "$(chroot "$root" xdg-mime query default $type)" = particlelab.desktop ] ||
    fail "xdg-mime does not name particlelab.desktop for $type"
done

part "clean root: apt-get remove, purge"
chroot "$root" dpkg -L particlelab >"$out/dpkg-L.txt"
in_root "apt-get remove -y -q particlelab | tail -n 1"
# Purged too (apt-get purge knows only packages of an archive: dpkg purges what remove may keep).
in_root "dpkg --purge particlelab && dpkg-query -W particlelab 2>&1 || true"
# Every path the package listed is gone, unless it is a folder another package still holds; the MIME
# database and the desktop files' cache, which triggers rebuilt, forget it.
left=()
while read -r path; do
  [ "$path" != /. ] || continue
  [ -e "$root$path" ] || [ -L "$root$path" ] || continue
  if [ -d "$root$path" ] && [ ! -L "$root$path" ] && chroot "$root" dpkg -S "$path" >/dev/null 2>&1; then continue; fi
  left+=("$path")
done <"$out/dpkg-L.txt"
for generated in /usr/share/mime/application/x-particlelab-experiment.xml \
  /usr/share/mime/application/x-particlelab-snapshot.xml; do
  [ ! -e "$root$generated" ] || left+=("$generated")
done
! grep -l particlelab "$root/usr/share/applications/mimeinfo.cache" || left+=(/usr/share/applications/mimeinfo.cache)
[ ${#left[@]} -eq 0 ] || fail "left behind after purge: ${left[*]}"
echo "removed and purged: none of the $(wc -l <"$out/dpkg-L.txt") paths of dpkg -L is left"

part ""
printf '\n== package: %s, %s\n' "$(basename "$deb")" "$(du -h "$deb" | cut -f1)"
printf '%s\n' "${parts[@]}"
