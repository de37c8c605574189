#include "ControllerRanks.h"

#include <stdexcept>

#include <vtkCommunicator.h>
#include <vtkMultiProcessController.h>

ControllerRanks::ControllerRanks(vtkMultiProcessController* controller) : Controller(controller) {}

int ControllerRanks::ranks() const { return Controller->GetNumberOfProcesses(); }
int ControllerRanks::rank() const { return Controller->GetLocalProcessId(); }

namespace {
template <class T>
void reduce(vtkMultiProcessController* c, std::vector<T>& v, int op) {
  std::vector<T> out(v.size());
  if (!c->AllReduce(v.data(), out.data(), static_cast<vtkIdType>(v.size()), op))
    throw std::runtime_error("aokit: a reduction across the ranks failed");
  v.swap(out);
}
}  // namespace

void ControllerRanks::minimum(std::vector<float>& values) { reduce(Controller, values, vtkCommunicator::MIN_OP); }
void ControllerRanks::minimum(std::vector<double>& values) { reduce(Controller, values, vtkCommunicator::MIN_OP); }
void ControllerRanks::minimum(std::vector<int>& values) { reduce(Controller, values, vtkCommunicator::MIN_OP); }
void ControllerRanks::bitwiseOr(std::vector<std::uint8_t>& bytes) {
  std::vector<unsigned char> out(bytes.size());
  if (!Controller->AllReduce(bytes.data(), out.data(), static_cast<vtkIdType>(bytes.size()), vtkCommunicator::BITWISE_OR_OP))
    throw std::runtime_error("aokit: a reduction across the ranks failed");
  bytes.assign(out.begin(), out.end());
}

std::vector<std::vector<std::uint8_t>> ControllerRanks::allGather(const std::vector<std::uint8_t>& mine) {
  const int n = ranks();
  std::vector<vtkIdType> lengths(n), offsets(n);
  const vtkIdType length = static_cast<vtkIdType>(mine.size());
  if (!Controller->AllGather(&length, lengths.data(), 1)) throw std::runtime_error("aokit: a gather across the ranks failed");
  vtkIdType total = 0;
  for (int r = 0; r < n; ++r) {
    offsets[r] = total;
    total += lengths[r];
  }
  std::vector<unsigned char> all(static_cast<std::size_t>(total) + 1);
  if (!Controller->AllGatherV(mine.data(), all.data(), length, lengths.data(), offsets.data()))
    throw std::runtime_error("aokit: a gather across the ranks failed");
  std::vector<std::vector<std::uint8_t>> out(n);
  for (int r = 0; r < n; ++r) out[r].assign(all.begin() + offsets[r], all.begin() + offsets[r] + lengths[r]);
  return out;
}
