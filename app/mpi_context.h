#pragma once
// The MPI scale-out of explore/optimize, reduced to the few collective operations the campaigns need. Built
// with -DHULLOPT_MPI=ON these use MPI; otherwise (the default) they are the one-process identities, so the
// commands have a single code path.
#include <string>
#include <vector>

#include "campaign/campaign_comm.h"

namespace hullopt::app {

/// Call once at the start/end of main. No-ops without MPI.
void MpiInit(int* argc, char*** argv);
void MpiFinalize();
/// After an error on any rank: stop all ranks (MPI_Abort) so that none waits forever; no-op with 1 process.
void MpiAbortIfParallel(int code);

int MpiRank();  ///< 0 without MPI
int MpiSize();  ///< 1 without MPI

/// Rank 0's text on every rank.
std::string MpiBroadcast(const std::string& text);
/// Every rank's text, in rank order, on rank 0 (other ranks get an empty list).
std::vector<std::string> MpiGather(const std::string& text);

/// The processes of this run as the campaign library sees them (MPI_COMM_WORLD, or the one process).
const campaign::CampaignComm& ProcessComm();

}  // namespace hullopt::app
