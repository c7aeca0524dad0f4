#!/usr/bin/env bash
# Installs what ParticleLab needs on Debian 12 (bookworm): the one package list both quick-start
# commands use, and with the argument "packaging" also what .ci/package.sh checks the Debian package
# with. Installs only what is missing; needs root or sudo when something is.
set -euo pipefail

packages=(
  # toolchain
  cmake g++ make pkg-config ca-certificates
  # man pages from the programs' --help, the icon's PNG sizes from its SVG (both at build time)
  help2man librsvg2-bin
  # Qt 6 widgets, OpenGL widgets, SVG, test; QCustomPlot's Qt 6 build
  qt6-base-dev libqt6opengl6-dev qt6-svg-dev libqcustomplot-dev
  # Qt Linguist: lupdate/lrelease, their CMake functions, and Qt's own strings in other languages
  qt6-l10n-tools qt6-tools-dev qt6-translations-l10n
  # recording clips through FFmpeg's libraries (ui/record/); ffprobe and pdftotext / pdftoppm read the
  # clips and reports back in the tests
  libavformat-dev libavcodec-dev libswscale-dev libavutil-dev ffmpeg poppler-utils
  # numerics, JSON, command line
  libeigen3-dev nlohmann-json3-dev libcli11-dev
  # OpenGL loading and headless contexts; Mesa's software renderer
  libepoxy-dev libegl-dev libgl1-mesa-dri libegl-mesa0 libglx-mesa0
  # an X server for the GUI tests; the style check
  xvfb xauth clang-format
  # LAMMPS (its binary is lmp) and Open MPI's mpirun: the scale-out agreement tests (docs/scale-out.md)
  lammps openmpi-bin
)
if [ "${1:-}" = packaging ]; then
  packages+=(
    # the package's checks: lintian, the freedesktop validators, man's warnings, a clean Debian root,
    # and the colours of its screenshot (netpbm)
    lintian desktop-file-utils appstream shared-mime-info man-db debootstrap netpbm
  )
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

if [ "$(id -u)" -eq 0 ]; then
  as_root=()
elif command -v sudo >/dev/null 2>&1; then
  as_root=(sudo)
else
  echo "install-deps: missing packages (${missing[*]}) and no root or sudo to install them" >&2
  exit 1
fi
echo "install-deps: installing ${missing[*]}" >&2
"${as_root[@]}" apt-get update -q
DEBIAN_FRONTEND=noninteractive "${as_root[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
