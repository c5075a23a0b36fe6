#pragma once
// Input files: every file PRT reads itself (scene, mesh, texture, checkpoint, report, cost
// map, port file) and every file it hands to another library is checked here first: it must
// exist and be a regular file — a FIFO would block until some writer comes, a device may
// never end (/dev/zero) or wait for input (a terminal) — and be no larger than the caller's
// bound (by default the memory budget, memory_budget.h), checked before anything is read.
// Thread-safe.

#include <cstdint>
#include <filesystem>
#include <string>

namespace prt {

// "a FIFO (named pipe)", "a character device", "a block device", "a socket"; empty for a
// regular file, a directory, or a file whose status cannot be read.
std::string specialFileKind(std::filesystem::file_type type);

// The size of the regular file `path`, or InputError: "<what> 'PATH' does not exist", "... is
// a directory", "... is a FIFO (named pipe), not a regular file", "... is 3.2 GiB, more than
// the 1.0 GiB a <what> may be". `what` names the file's role ("mesh file", "checkpoint").
uint64_t checkInputFile(const std::string& path, const std::string& what, uint64_t maxBytes);
uint64_t checkInputFile(const std::string& path, const std::string& what);  // the budget

// Its bytes, after checkInputFile's checks; a file that grows past the bound while it is
// read is refused too.
std::string readInputFile(const std::string& path, const std::string& what, uint64_t maxBytes);
std::string readInputFile(const std::string& path, const std::string& what);

}  // namespace prt
