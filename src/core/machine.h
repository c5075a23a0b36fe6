#pragma once
// What machine this process runs on, for summaries and reports: the processor's model name,
// the host name and the operating system. Each reads the system once per call; thread-safe.

#include <string>

namespace prt {

std::string cpuModel();  // "AMD EPYC 7B13" from /proc/cpuinfo; "unknown CPU" where unreadable
std::string hostName();  // gethostname(); "unknown host" on failure
// "AMD EPYC 7B13, 2 cores, host build-1, Linux 6.1.0-18-amd64 x86_64".
std::string describeMachine();

}  // namespace prt
