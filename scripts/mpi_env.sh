# Sourced by the project's scripts before they run mpirun. Open MPI refuses to start as root (the
# usual user in containers and CI) unless two variables are set; say so in one line, then set them
# for this script's runs. Oversubscription lets a deck ask for more ranks than the machine has cores.
if [ "$(id -u)" -eq 0 ] && [ -z "${OMPI_ALLOW_RUN_AS_ROOT:-}" ]; then
  echo "[liggghts-crush] running as root: Open MPI's mpirun needs 'export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1' (or --allow-run-as-root); set for this script's runs" >&2
fi
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
