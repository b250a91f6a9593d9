/* Counts the global collectives of each time step on rank 0, for test_penetration's cone_collectives.
 * Preloaded into liggghts (LD_PRELOAD), it defines the MPI collectives, counts each call and passes it
 * to the PMPI_ version. A step is delimited by fix wall/servo's reduction of its walls (one
 * MPI_Allreduce of 9 doubles, MPI_SUM, in every post_force): the calls between two of them, that one
 * included, are one step's. At MPI_Finalize rank 0 writes to $COUNT_COLLECTIVES_OUT one line per
 * count seen: "collectives steps". */
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>

#define MAX_COUNT 1024
static long histogram[MAX_COUNT + 1];
static int since_delimiter = -1; /* -1: before the first delimiter */

static int on_rank0(void)
{
  int rank = 1, up = 0;
  MPI_Initialized(&up);
  if (up) PMPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank == 0;
}

static void count(int delimiter)
{
  if (!on_rank0()) return;
  if (delimiter) {
    if (since_delimiter >= 0) histogram[since_delimiter < MAX_COUNT ? since_delimiter : MAX_COUNT]++;
    since_delimiter = 0;
  }
  if (since_delimiter >= 0) since_delimiter++;
}

int MPI_Allreduce(const void *s, void *r, int n, MPI_Datatype t, MPI_Op op, MPI_Comm c)
{
  count(n == 9 && t == MPI_DOUBLE && op == MPI_SUM);
  return PMPI_Allreduce(s, r, n, t, op, c);
}
int MPI_Reduce(const void *s, void *r, int n, MPI_Datatype t, MPI_Op op, int root, MPI_Comm c)
{
  count(0);
  return PMPI_Reduce(s, r, n, t, op, root, c);
}
int MPI_Allgather(const void *s, int ns, MPI_Datatype ts, void *r, int nr, MPI_Datatype tr, MPI_Comm c)
{
  count(0);
  return PMPI_Allgather(s, ns, ts, r, nr, tr, c);
}
int MPI_Allgatherv(const void *s, int ns, MPI_Datatype ts, void *r, const int *nr, const int *d, MPI_Datatype tr,
                   MPI_Comm c)
{
  count(0);
  return PMPI_Allgatherv(s, ns, ts, r, nr, d, tr, c);
}
int MPI_Bcast(void *b, int n, MPI_Datatype t, int root, MPI_Comm c)
{
  count(0);
  return PMPI_Bcast(b, n, t, root, c);
}
int MPI_Barrier(MPI_Comm c)
{
  count(0);
  return PMPI_Barrier(c);
}
int MPI_Scan(const void *s, void *r, int n, MPI_Datatype t, MPI_Op op, MPI_Comm c)
{
  count(0);
  return PMPI_Scan(s, r, n, t, op, c);
}
int MPI_Reduce_scatter(const void *s, void *r, const int *n, MPI_Datatype t, MPI_Op op, MPI_Comm c)
{
  count(0);
  return PMPI_Reduce_scatter(s, r, n, t, op, c);
}
int MPI_Alltoall(const void *s, int ns, MPI_Datatype ts, void *r, int nr, MPI_Datatype tr, MPI_Comm c)
{
  count(0);
  return PMPI_Alltoall(s, ns, ts, r, nr, tr, c);
}

int MPI_Finalize(void)
{
  const char *path = getenv("COUNT_COLLECTIVES_OUT");
  if (path && on_rank0()) {
    FILE *f = fopen(path, "w");
    if (f) {
      for (int k = 0; k <= MAX_COUNT; k++)
        if (histogram[k]) fprintf(f, "%d %ld\n", k, histogram[k]);
      fclose(f);
    }
  }
  return PMPI_Finalize();
}
