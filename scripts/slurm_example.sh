#!/usr/bin/env bash
# Example Slurm batch script: one pound run (a suite or a gap sweep) over 64 MPI ranks on
# two nodes. Submit with `sbatch scripts/slurm_example.sh DECK.nml`; adapt the module names,
# the partition and the resources to your cluster. pound must be built with MPI:
#   cmake -S . -B build/mpi -DCMAKE_BUILD_TYPE=Release -DPOUND_MPI=ON && cmake --build build/mpi --target pound
# Every rank reads the deck (and its records) from the shared file system; rank 0 alone
# writes DIR/<deck>.out and DIR/<deck>.h5.
#SBATCH --job-name=pound
#SBATCH --nodes=2
#SBATCH --ntasks-per-node=32
#SBATCH --cpus-per-task=1
#SBATCH --time=01:00:00
#SBATCH --output=pound-%j.log
set -euo pipefail
deck="${1:?usage: sbatch scripts/slurm_example.sh DECK.nml [OUTPUT_DIR]}"
out="${2:-out}"
# module load gcc openmpi hdf5 lapack      # as your cluster provides them
export OMP_NUM_THREADS=1                   # one core per rank (LAPACK/BLAS single-threaded)
# srun starts the ranks under Slurm (Open MPI built with Slurm/PMIx support); otherwise
# `mpirun -np "$SLURM_NTASKS" build/mpi/pound ...` does the same.
srun build/mpi/pound "$deck" -o "$out" --quiet
