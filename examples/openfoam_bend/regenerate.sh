#!/bin/bash
# Regenerate the OpenFOAM reference run of examples/openfoam_bend from scratch, with Debian's `openfoam` package
# (v1912, 1912.200626), serial, and copy the small outputs into wear/app/data/openfoam_bend/ (see README.md).
#
#   ./regenerate.sh [WORK_DIR]      (default: a new temporary directory; the run itself takes well under a minute)
#
# Steps: blockMesh (a straight O-grid pipe), bend_points.py (bends and twists it into the 90 deg bend), checkMesh,
# simpleFoam (steady air flow), then icoUncoupledKinematicParcelFoam (sand parcels through the frozen flow, with the
# patchPostProcessing and particleErosion cloud functions on the three wall patches).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
work="${1:-$(mktemp -d /tmp/openfoam_bend.XXXXXX)}"
out="$(cd "$here/../.." && pwd)/wear/app/data/openfoam_bend"

# Debian's bashrc sets WM_PROJECT_DIR etc. (the solvers need it to find etc/controlDict); it also complains about
# the missing foamEtcFile/foamCleanPath helpers, which is harmless.
set +eu
# shellcheck disable=SC1091
source /usr/share/openfoam/etc/bashrc >/dev/null 2>&1
set -eu
command -v icoUncoupledKinematicParcelFoam >/dev/null || { echo "regenerate.sh: OpenFOAM (Debian package openfoam) not found" >&2; exit 2; }

mkdir -p "$work"
rm -rf "$work/flow" "$work/particles"
cp -r "$here/flow" "$here/particles" "$work/"
echo "work directory: $work"

cd "$work/flow"
blockMesh > log.blockMesh 2>&1
python3 "$here/bend_points.py" .
checkMesh > log.checkMesh 2>&1
simpleFoam > log.simpleFoam 2>&1
flow_time="$(foamListTimes -latestTime 2>/dev/null | tail -1)"
[ -n "$flow_time" ] || flow_time="$(ls -d [0-9]* | sort -g | tail -1)"
echo "steady flow: $flow_time iterations"

cd "$work/particles"
mkdir -p 0
cp "$work/flow/$flow_time/U" 0/U
cp -r "$work/flow/constant/polyMesh" constant/
icoUncoupledKinematicParcelFoam > log.icoUncoupledKinematicParcelFoam 2>&1
last="$(ls -d [0-9]* | sort -g | tail -1)"
echo "particles: end time $last"

# The small outputs, written to a fresh directory and moved into place (earlier outputs are replaced as a whole).
tmp="$(mktemp -d "$(dirname "$out")/.openfoam_bend.XXXXXX")"
chmod 755 "$tmp"
pp=postProcessing/lagrangian/kinematicCloud/patchPostProcessing1
for t in $(ls "$pp" | sort -g); do
    mkdir -p "$tmp/patchPostProcessing1/$t"
    for f in "$pp/$t"/*.post; do
        gzip -9 -n -c "$f" > "$tmp/patchPostProcessing1/$t/$(basename "$f").gz"
    done
done
cp "$last/kinematicCloudQ" "$tmp/kinematicCloudQ"
gzip -9 -n "$tmp/kinematicCloudQ"
mkdir -p "$tmp/polyMesh"
for f in points faces owner boundary; do
    cp "constant/polyMesh/$f" "$tmp/polyMesh/$f"
done
gzip -9 -n "$tmp/polyMesh/points" "$tmp/polyMesh/faces" "$tmp/polyMesh/owner"
{
    echo "# Build/Exec lines of the logs"
    for log in "$work"/flow/log.* "$work"/particles/log.*; do
        echo "$(basename "$log"): $(grep -m1 '^Build' "$log")"
    done
    echo "checkMesh: $(grep -E 'Mesh OK|Failed' "$work/flow/log.checkMesh" | head -1)"
    echo "simpleFoam: $(grep -E 'converged in|^End' "$work/flow/log.simpleFoam" | head -1)"
} > "$tmp/versions.txt"
# The cloud's last report (parcels injected, escaped, still in flight) and the run times.
{
    grep -m1 '^Build' log.icoUncoupledKinematicParcelFoam
    awk '/^Time = /{block=""} {block=block $0 "\n"} END{printf "%s", block}' log.icoUncoupledKinematicParcelFoam
    grep -E '^ExecutionTime' "$work/flow/log.simpleFoam" | tail -1 | sed 's/^/simpleFoam: /'
} > "$tmp/cloud_summary.txt"
rm -rf "$out.old"
[ -d "$out" ] && mv "$out" "$out.old"
mv "$tmp" "$out"
rm -rf "$out.old"
echo "outputs: $out"
