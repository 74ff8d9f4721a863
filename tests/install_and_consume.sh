#!/usr/bin/env bash
# cmake --install into a temporary prefix, then use only what was installed:
# the programs' --version, a program of one's own built against the
# installed CMake package (tests/install_consumer: find_package(FE2DEM),
# one RVE solve), and the demo of the installed share folder (the [LBS]
# biaxial test on one element, shortened to 1 + 1 load steps, 2 ranks).
# Usage: install_and_consume.sh BUILD_DIR WORK_DIR CONSUMER_SOURCE
set -euo pipefail
build=$1 work=$2 consumer=$3
rm -rf "$work"; mkdir -p "$work"
prefix="$work/prefix"
cmake --install "$build" --prefix "$prefix" > "$work/install.log"
fail() { echo "FAIL: $*"; exit 1; }
for exe in fe2dem fe2dem-rve fe2dem-liggghts; do
  v=$("$prefix/bin/$exe" --version) || fail "$exe --version"
  echo "$v"
  [[ $v =~ ^$exe\ [0-9]+\.[0-9]+\.[0-9]+\ \(git\ [^\)]+\) ]] || fail "$exe --version printed '$v'"
done
for f in include/fe2dem/servo_rve_factory.h lib/libfe2dem_coupler.a lib/cmake/FE2DEM/FE2DEMConfig.cmake \
         share/fe2dem/rve_templates/rve_setup_3d.liggghts share/fe2dem/rve_templates/packings/lbs_ref.rve.data \
         share/fe2dem/examples/macro/biaxial_1x1.prm; do
  [[ -f "$prefix/$f" ]] || fail "not installed: $f"
done
cmake -S "$consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$prefix" > "$work/consumer.log" 2>&1 \
  || { tail -n 20 "$work/consumer.log"; fail "configuring the consumer against the installed package"; }
cmake --build "$work/consumer" >> "$work/consumer.log" 2>&1 \
  || { tail -n 20 "$work/consumer.log"; fail "building the consumer"; }
(cd "$work" && FE2DEM_LIGGGHTS="$prefix/bin/fe2dem-liggghts" "$work/consumer/one_rve") || fail "the consumer's RVE solve"
# The demo, from the installed share folder (its relative paths point there).
examples="$prefix/share/fe2dem/examples/macro"
{ cat "$examples/biaxial_1x1.prm"
  printf '\nset Output directory = %s\nsubsection Loading\n  set Isotropic steps = 1\n  set Load steps = 1\n  set Axial strain = 0.001\nend\n' "$work/demo"
} > "$examples/demo_short.prm"
mpiexec --allow-run-as-root --oversubscribe -np 2 "$prefix/bin/fe2dem" "$examples/demo_short.prm" > "$work/demo.log" 2>&1 \
  || { tail -n 5 "$work/demo.log"; fail "the installed demo"; }
rows=$(($(wc -l < "$work/demo/summary.csv") - 1))
[[ $rows -eq 2 ]] || fail "the installed demo wrote $rows summary rows, expected 2"
echo "ok: installed to $prefix; --version x3, consumer built and solved one RVE, demo wrote $rows rows"
