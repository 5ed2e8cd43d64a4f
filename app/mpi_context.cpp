#include "app/mpi_context.h"

#ifdef HULLOPT_HAVE_MPI
#include <mpi.h>
#endif

namespace hullopt::app {

#ifdef HULLOPT_HAVE_MPI

void MpiInit(int* argc, char*** argv) {
  int provided = 0;
  MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);  // OpenMP threads never call MPI
}
void MpiFinalize() { MPI_Finalize(); }
void MpiAbortIfParallel(int code) {
  if (MpiSize() > 1) MPI_Abort(MPI_COMM_WORLD, code);
}
int MpiRank() {
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}
int MpiSize() {
  int s = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &s);
  return s;
}
std::string MpiBroadcast(const std::string& text) {
  long long n = static_cast<long long>(text.size());
  MPI_Bcast(&n, 1, MPI_LONG_LONG, 0, MPI_COMM_WORLD);
  std::string out = MpiRank() == 0 ? text : std::string(static_cast<std::size_t>(n), '\0');
  if (n > 0) MPI_Bcast(out.data(), static_cast<int>(n), MPI_CHAR, 0, MPI_COMM_WORLD);
  return out;
}
std::vector<std::string> MpiGather(const std::string& text) {
  const int size = MpiSize(), rank = MpiRank();
  int n = static_cast<int>(text.size());
  std::vector<int> counts(size), displs(size);
  MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::string all;
  if (rank == 0) {
    int total = 0;
    for (int r = 0; r < size; ++r) {
      displs[r] = total;
      total += counts[r];
    }
    all.resize(static_cast<std::size_t>(total));
  }
  MPI_Gatherv(text.data(), n, MPI_CHAR, all.data(), counts.data(), displs.data(), MPI_CHAR, 0,
              MPI_COMM_WORLD);
  std::vector<std::string> out;
  if (rank == 0)
    for (int r = 0; r < size; ++r) out.push_back(all.substr(displs[r], counts[r]));
  return out;
}

#else

void MpiInit(int*, char***) {}
void MpiFinalize() {}
void MpiAbortIfParallel(int) {}
int MpiRank() { return 0; }
int MpiSize() { return 1; }
std::string MpiBroadcast(const std::string& text) { return text; }
std::vector<std::string> MpiGather(const std::string& text) { return {text}; }

#endif

namespace {

class ProcessCommImpl : public campaign::CampaignComm {
 public:
  int Rank() const override { return MpiRank(); }
  int Size() const override { return MpiSize(); }
  std::string Broadcast(const std::string& text) const override { return MpiBroadcast(text); }
  std::vector<std::string> Gather(const std::string& text) const override { return MpiGather(text); }
};

}  // namespace

const campaign::CampaignComm& ProcessComm() {
  static const ProcessCommImpl comm;
  return comm;
}

}  // namespace hullopt::app
