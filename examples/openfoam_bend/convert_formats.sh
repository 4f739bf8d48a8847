#!/bin/bash
# Rewrite the committed bend run's polyMesh and its kinematicCloudQ field (wear/app/data/openfoam_bend) in OpenFOAM's
# other file formats, with OpenFOAM's own foamFormatConvert (Debian's `openfoam` package, v1912, 1912.200626), into
# the test data of tests/test_wall_foam_formats.py (the suite itself does not need OpenFOAM):
#
#   tests/data/openfoam_bend_binary/      writeFormat binary  (v1912 writes binary files uncompressed, even with
#                                         writeCompression on: "Disabled binary format compression")
#   tests/data/openfoam_bend_compressed/  writeFormat ascii; writeCompression on  (every file gets .gz, boundary too)
#
# each as a case: constant/polyMesh/{boundary,points,faces} and 0.12/kinematicCloudQ (the owner file is converted
# too but not kept: the wall does not read it).
#
#   ./convert_formats.sh [WORK_DIR]      (default: a new temporary directory; a few seconds)
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
src="$root/wear/app/data/openfoam_bend"
work="${1:-$(mktemp -d /tmp/openfoam_formats.XXXXXX)}"

# Debian's bashrc complains about missing helpers, harmlessly (see regenerate.sh).
set +eu
# shellcheck disable=SC1091
source /usr/share/openfoam/etc/bashrc >/dev/null 2>&1
set -eu
command -v foamFormatConvert >/dev/null || { echo "convert_formats.sh: OpenFOAM (Debian package openfoam) not found" >&2; exit 2; }
echo "work directory: $work"

convert() {  # convert NAME FORMAT COMPRESSION
    local case="$work/$1"
    rm -rf "$case"
    mkdir -p "$case/constant/polyMesh" "$case/system" "$case/0.12"
    cp "$src/polyMesh/boundary" "$case/constant/polyMesh/"
    for f in points faces owner; do
        gzip -dc "$src/polyMesh/$f.gz" > "$case/constant/polyMesh/$f"
    done
    gzip -dc "$src/kinematicCloudQ.gz" > "$case/0.12/kinematicCloudQ"
    cat > "$case/system/controlDict" <<EOF
FoamFile { version 2.0; format ascii; class dictionary; location "system"; object controlDict; }
application     foamFormatConvert;
startFrom       latestTime;
startTime       0;
stopAt          endTime;
endTime         0.12;
deltaT          1;
writeControl    timeStep;
writeInterval   1;
writeFormat     $2;
writePrecision  17;     // the values as read: the ascii rewrite loses nothing
writeCompression $3;
timeFormat      general;
timePrecision   6;
EOF
    (cd "$case" && foamFormatConvert -constant > log.foamFormatConvert 2>&1)
    local out="$root/tests/data/openfoam_bend_$1"
    rm -rf "$out"
    mkdir -p "$out/constant/polyMesh" "$out/0.12"
    for f in boundary points faces; do
        cp "$case/constant/polyMesh/$f"* "$out/constant/polyMesh/"
    done
    cp "$case/0.12/kinematicCloudQ"* "$out/0.12/"
    echo "$1: $(grep -m1 '^Build' "$case/log.foamFormatConvert") -> $out"
}

convert binary binary off
convert compressed ascii on
