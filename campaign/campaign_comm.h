#pragma once
// The few collective operations a campaign needs to spread its work over processes (MPI ranks). The library
// holds no MPI: a campaign runs on the one process of SerialComm() unless the caller hands it another
// CampaignComm (the hullopt command line built with -DHULLOPT_MPI=ON hands it one over MPI_COMM_WORLD,
// app/mpi_context.h).
#include <string>
#include <vector>

namespace hullopt::campaign {

class CampaignComm {
 public:
  virtual ~CampaignComm() = default;
  virtual int Rank() const = 0;  ///< this process, 0..Size()-1
  virtual int Size() const = 0;  ///< the number of processes
  /// Rank 0's text on every rank.
  virtual std::string Broadcast(const std::string& text) const = 0;
  /// Every rank's text, in rank order, on rank 0 (other ranks get an empty list).
  virtual std::vector<std::string> Gather(const std::string& text) const = 0;
};

/// One process: rank 0 of 1; Broadcast and Gather are identities.
const CampaignComm& SerialComm();

}  // namespace hullopt::campaign
