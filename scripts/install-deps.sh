#!/usr/bin/env bash
# Installs the Debian 12 packages FE2DEM builds and runs with, only those missing.
# Used by run-tests.sh and run-demo.sh; safe to run repeatedly.
set -euo pipefail

packages=(
  cmake g++ make pkg-config
  libliggghts-dev liggghts          # LIGGGHTS 3.8: library, headers, reference binary
  libdeal.ii-dev                    # deal.II 9.4 (macro solver, parameter files)
  libopenmpi-dev openmpi-bin        # MPI
  libeigen3-dev                     # tensors in the coupler
  libhdf5-openmpi-dev               # the HDF5 build deal.II links (see architecture.md)
  python3 python3-numpy python3-matplotlib python3-h5py   # plots, post-processing
  python3-vtk9                      # tests read the VTU outputs as ParaView does (VTK 9.1)
  slurmctld slurmd slurm-client munge   # the batch script's test on a one-node SLURM
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if ((${#missing[@]})); then
  echo "install-deps: installing ${missing[*]}"
  SUDO=""
  [[ $(id -u) -ne 0 ]] && SUDO="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -q
  $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
else
  echo "install-deps: all ${#packages[@]} packages present"
fi
