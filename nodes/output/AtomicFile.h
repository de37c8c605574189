#pragma once
// Writes go to "<path>.tmp-<pid>" and are renamed into place only when complete, so an error or
// Ctrl-C never leaves a half-written output file.
#include <functional>
#include <string>

namespace aokit {

// Calls write(tmpPath); on success renames tmpPath to path, on any exception removes it and rethrows.
void writeAtomically(const std::string& path, const std::function<void(const std::string& tmpPath)>& write);

// Creates a directory (and parents); throws a one-line error when it cannot.
void ensureDirectory(const std::string& dir);

}  // namespace aokit
