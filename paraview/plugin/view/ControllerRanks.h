#ifndef ControllerRanks_h
#define ControllerRanks_h
// The kit's RankExchange (parallel/RankExchange.h) over ParaView's global vtkMultiProcessController
// (MPI under mpiexec): what makes the AO of N ranks the AO of one process.
#include "parallel/RankExchange.h"

class vtkMultiProcessController;

class ControllerRanks : public aokit::RankExchange
{
public:
  explicit ControllerRanks(vtkMultiProcessController* controller);
  int ranks() const override;
  int rank() const override;
  void minimum(std::vector<float>& values) override;
  void minimum(std::vector<double>& values) override;
  void minimum(std::vector<int>& values) override;
  void bitwiseOr(std::vector<std::uint8_t>& bytes) override;
  std::vector<std::vector<std::uint8_t>> allGather(const std::vector<std::uint8_t>& mine) override;

private:
  vtkMultiProcessController* Controller;  // the process's global controller: outlives every view
};

#endif
