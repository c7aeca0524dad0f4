#!/bin/sh
# Records the test data of the named kinds or presets only, leaving every other file as it is:
#   - the golden runs (golden/runs.txt) of the presets named, or of every preset of a kind named;
#   - a kind's snapshot pair (snapshots/recipes.txt), only where the kind has none yet: the pairs that
#     exist were written by an earlier build on purpose (snapshots/README.md);
#   - with --translations, the catalogue's entries for new texts (the update_translations target, which
#     adds the sources' new texts as unfinished entries and keeps every translated one).
#
#   tests/data/record.sh [--cli PATH] [--build DIR] [--translations] NAME...
#
# NAME is a kind (gas, fluid, ...) or a preset (fluid-obstacle). Run from anywhere; the files it writes are
# listed at the end. Exit 2 for a name that matches nothing, so a typo records nothing.
set -eu

here=$(cd "$(dirname "$0")" && pwd)
build="$here/../../build"
cli=""
translations=no
while [ $# -gt 0 ]; do
    case "$1" in
    --cli) cli="$2"; shift 2 ;;
    --build) build="$2"; shift 2 ;;
    --translations) translations=yes; shift ;;
    -h | --help) sed -n '2,13p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "record.sh: unknown option $1" >&2; exit 2 ;;
    *) break ;;
    esac
done
[ $# -gt 0 ] || { echo "record.sh: name a kind or a preset (--help)" >&2; exit 2; }
[ -n "$cli" ] || cli="$build/app/particlelab-cli"
[ -x "$cli" ] || { echo "record.sh: no particlelab-cli at $cli (build it, or give --cli)" >&2; exit 2; }

# A golden line or a recipe belongs to NAME when its preset is NAME or starts with "NAME-" (the kinds'
# presets are named <kind>-*, docs/architecture.md).
matches() { # preset name...
    preset=$1
    shift
    for name in "$@"; do
        case "$preset" in "$name" | "$name"-*) return 0 ;; esac
    done
    return 1
}

for name in "$@"; do
    if ! grep -v '^#' "$here/golden/runs.txt" | awk '{print $1}' | grep -q -e "^$name\$" -e "^$name-"; then
        echo "record.sh: '$name' is neither a kind nor a preset of golden/runs.txt" >&2
        exit 2
    fi
done

grep -v '^#' "$here/golden/runs.txt" | while read -r preset steps every particles; do
    matches "$preset" "$@" || continue
    if [ "$particles" = yes ]; then
        "$cli" run "$preset" --steps "$steps" --every "$every" --quiet --threads 1 \
            --out "$here/golden/$preset.series.csv" --dump-final "$here/golden/$preset.particles.csv"
        echo "golden/$preset.series.csv golden/$preset.particles.csv"
    else
        "$cli" run "$preset" --steps "$steps" --every "$every" --quiet --threads 1 \
            --out "$here/golden/$preset.series.csv"
        echo "golden/$preset.series.csv"
    fi
done

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
grep -v '^#' "$here/snapshots/recipes.txt" | while read -r file preset options; do
    [ -n "$file" ] || continue
    matches "$preset" "$@" || continue
    [ -e "$here/snapshots/$file.snapshot.json" ] && continue # an earlier build's pair stays
    # shellcheck disable=SC2086 # the recipe's options are words
    "$cli" run "$preset" $options --threads 1 --quiet --out "$scratch/series.csv" \
        --snapshot "$here/snapshots/$file.snapshot.json"
    "$cli" run "$here/snapshots/$file.snapshot.json" --steps 30 --threads 1 --quiet --out "$scratch/series.csv" \
        --dump-final "$here/snapshots/$file.after30.csv"
    echo "snapshots/$file.snapshot.json snapshots/$file.after30.csv"
done

if [ "$translations" = yes ]; then
    cmake --build "$build" --target update_translations >/dev/null
    echo "resources/translations/particlelab_de.ts (new entries unfinished: translate them)"
fi
