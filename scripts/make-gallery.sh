#!/usr/bin/env bash
# Runs every example as shipped (each with the one command of the README's
# examples table; outputs in output/NAME) and draws one picture of each into
# docs/gallery/NAME.png, the pictures of docs/gallery.md, and each command with
# its wall time into docs/gallery/times.txt. About 9 minutes on
# 2 cores. Builds in build/ first unless BUILD names a build directory.
# Usage: scripts/make-gallery.sh [BUILD]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build=${1:-}
if [[ -z $build ]]; then
  "$root/scripts/install-deps.sh"
  cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release
  cmake --build "$root/build" -j "$(nproc)"
  build=$root/build
fi
build=$(cd "$build" && pwd)
fe2dem=$build/dealii_app/solver/fe2dem rve=$build/dealii_app/rve_driver/fe2dem-rve
mpi=(mpirun --allow-run-as-root --oversubscribe -np 2)
gallery=$root/docs/gallery
mkdir -p "$gallery"
cd "$root"

# name | kind (scripts/plot_gallery.py) | command | title
examples=(
  "biaxial_1x1|macro|${mpi[*]} $fe2dem dealii_app/examples/biaxial_1x1.prm|2D biaxial test, one element, 4 RVEs"
  "biaxial_2x4|macro|${mpi[*]} $fe2dem dealii_app/examples/biaxial_2x4.prm|2D biaxial test, 2 x 4 mesh, 32 RVEs (recommended scheme)"
  "biaxial_gmsh|macro|${mpi[*]} $fe2dem dealii_app/examples/biaxial_gmsh.prm|2D biaxial test on an unstructured Gmsh mesh, 5 quads, 20 RVEs"
  "elastic_block|elastic|$fe2dem dealii_app/examples/elastic_block.prm|2D neo-Hookean block, 2 % compression"
  "elastic_block_3d|elastic|$fe2dem dealii_app/examples/elastic_block_3d.prm|3D neo-Hookean block, distorted mesh, triaxial"
  "triaxial_3d_rve|macro|$fe2dem dealii_app/examples/triaxial_3d_rve.prm|3D triaxial compression of one element with a small_3d RVE"
  "simple_shear_3d_rve|shear|$fe2dem dealii_app/examples/simple_shear_3d_rve.prm|3D simple shear of one element with a small_3d RVE, boundary conditions from the file"
  "wave_column_3d_rve|wave|${mpi[*]} $fe2dem dealii_app/examples/wave_column_3d_rve.prm|3D wave column, 4 lsyf_1000 Hertz RVEs, explicit dynamics"
  "rve_isotropic_2d|rve|$rve rve_templates/examples/isotropic_2d.prm|one 2D RVE, isotropic compression"
  "rve_biaxial_2d|rve|$rve rve_templates/examples/biaxial_2d.prm|one 2D RVE, biaxial compression"
  "rve_simple_shear_2d|rve|$rve rve_templates/examples/simple_shear_2d.prm|one 2D RVE, simple shear"
  "rve_triaxial_3d|rve|$rve rve_templates/examples/triaxial_3d.prm|one 3D RVE (small_3d), triaxial compression"
)
times=$gallery/times.txt
echo "# example, wall seconds, command ($(date -u +%Y-%m-%d), $(nproc) cores, scripts/make-gallery.sh)" > "$times.tmp"
for e in "${examples[@]}"; do
  IFS='|' read -r name kind command title <<<"$e"
  echo "== $name: $command"
  rm -rf "output/$name" "output/$name.log"
  start=$(date +%s)
  mkdir -p output
  $command > "output/$name.log" 2>&1 || { echo "make-gallery: $name failed, see output/$name.log"; exit 1; }
  echo "   $(($(date +%s) - start)) s"
  echo "$name $(($(date +%s) - start)) ${command//$build/build}" >> "$times.tmp"
  /usr/bin/python3 "$root/scripts/plot_gallery.py" "$kind" "output/$name" "$gallery/$name.png" "$title"
done
mv "$times.tmp" "$times"
