#ifndef vefs_mpi_concatenate_h
#define vefs_mpi_concatenate_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <limits>
#include <type_traits>
#include <vector>

namespace vefs
{
  /**
   * The vectors @p local of all ranks, one after the other in rank order, on
   * every rank. For plain data (points, tensors, indices): sent as bytes,
   * where Utilities::MPI::all_gather() serializes each element (3D ball at
   * 2.5 mm: half the redistancing's time went into packing its surface
   * points).
   */
  template <typename T>
  std::vector<T>
  concatenated_over_ranks(const MPI_Comm comm, const std::vector<T> &local)
  {
    static_assert(std::is_trivially_copyable_v<T>,
                  "sent as bytes: plain data only");
    const unsigned long long local_bytes = local.size() * sizeof(T);
    AssertThrow(local_bytes <= std::numeric_limits<int>::max(),
                dealii::ExcMessage("more than 2 GiB to gather from a rank"));
    const int          n_ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
    const int          bytes   = static_cast<int>(local_bytes);
    std::vector<int>   all_bytes(n_ranks), offsets(n_ranks);
    unsigned long long total = 0;
    int                ierr =
      MPI_Allgather(&bytes, 1, MPI_INT, all_bytes.data(), 1, MPI_INT, comm);
    AssertThrowMPI(ierr);
    for (int rank = 0; rank < n_ranks; ++rank)
      {
        AssertThrow(total <= std::numeric_limits<int>::max(),
                    dealii::ExcMessage("more than 2 GiB to gather"));
        offsets[rank] = static_cast<int>(total);
        total += all_bytes[rank];
      }
    std::vector<T> all(total / sizeof(T));
    ierr = MPI_Allgatherv(local.data(),
                          bytes,
                          MPI_BYTE,
                          all.data(),
                          all_bytes.data(),
                          offsets.data(),
                          MPI_BYTE,
                          comm);
    AssertThrowMPI(ierr);
    return all;
  }
} // namespace vefs

#endif
