#pragma once
// What this build is, as a worker says it in its speed-index message and a joiner in its
// invitation: PRT's version and the build of its trace kernels (the machine's name is
// core/machine.h's hostName()).
//
// The version rule (Master, net/invitation.h): workers of another PRT version are refused or
// rejected; the trace kernels' ISA level may differ, since every build renders the same bits
// (tested, and watched at run time by the spot checks).

#include <string>

namespace prt {

std::string prtVersion();        // "0.1.0"
std::string buildDescription();  // "prt 0.1.0 (trace kernels: x86-64-v3)", as `prt --version`
// The version of a build description ("prt 0.1.0 (...)" -> "0.1.0"); empty if it is none.
std::string versionOf(const std::string& build);

}  // namespace prt
