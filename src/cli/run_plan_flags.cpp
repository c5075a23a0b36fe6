#include "cli/run_plan_flags.h"

#include <cstdint>
#include <string_view>

#include "cli/flag_checks.h"
#include "cluster/leases.h"
#include "core/input_error.h"
#include "core/speed_schedule.h"

namespace prt::cli {
namespace {

// Digits only (no sign, no space), at most `max`: sscanf's %llu would take "-5" as 2^64 - 5.
std::optional<uint64_t> parseCount(std::string_view text, uint64_t max) {
  if (text.empty() || text.size() > 19) return std::nullopt;
  uint64_t value = 0;
  for (const char c : text) {
    if (c < '0' || c > '9') return std::nullopt;
    value = value * 10 + static_cast<uint64_t>(c - '0');
  }
  if (value > max) return std::nullopt;
  return value;
}

}  // namespace

void addRunPlanFlags(CLI::App& cmd, RunPlanFlags& f, const RunPlanFlagGroups& groups) {
  const bool sim = groups.simulated;
  cmd.add_option("--batch", f.batchPixels, "Pixels a worker renders between returning results")
      ->check(CLI::Range(1ull, 1ull << 28))  // no image has more pixels; "-1" would wrap
      ->capture_default_str()
      ->group(groups.batches);
  cmd.add_option("--worker-timeout", f.workerTimeoutSeconds,
                 std::string("Seconds of silence (no message, not even a heartbeat) after which a "
                             "worker is declared lost and its tasks go to the others; heartbeats "
                             "go after a fifth of it in silence") +
                     (sim ? " (the master's modelled load counts them)" : "") +
                     ". Default: 5 s, longer past 10,000 workers (0.5 ms per worker) so that "
                     "heartbeats never keep one master more than 5 % busy")
      ->check(finiteIn(kMinLeaseSeconds, kMaxLeaseSeconds))
      ->default_str("auto")
      ->group(groups.batches);
  cmd.add_option("--endgame", f.endgame,
                 "on: when nothing is left to hand out, an idle worker renders a copy of the "
                 "tasks expected to finish last (the first result wins)")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str()
      ->group(groups.batches);
  cmd.add_option("--join-at", f.joinAt,
                 std::string("Workers that join the running render") +
                     (sim ? "" : " (local driver)") + ": T:K,... adds K workers T" +
                     (sim ? " virtual" : "") +
                     " seconds in, numbered after the others in the order they join (" +
                     (sim ? "--speeds" : "--slowdown") +
                     " then lists every worker, joiners included)")
      ->group(groups.joins);
  cmd.add_option("--inject-fault", f.faults,
                 sim ? "WORKER:PIXELS:crash|hang, as in prt render: the worker fails before its "
                       "next batch once it has rendered PIXELS; a crash drops its connection "
                       "(lost at once), a hang goes silent (lost after --worker-timeout)"
                     : "WORKER:PIXELS:crash|hang|corrupt makes worker WORKER (rank WORKER+1 "
                       "under MPI) fail after rendering that many pixels; corrupt: return wrong "
                       "pixels from then on (a bit flipped in about half of them)")
      ->group(groups.failures);
}

RunPlan runPlanFrom(const RunPlanFlags& f, int startingWorkers) {
  RunPlan plan;
  plan.strategy = f.strategyFlags.name();
  plan.strategyOptions = strategyOptionsFrom(f.strategyFlags);
  plan.batchPixels = f.batchPixels;
  plan.endgame = f.endgame == "on";
  if (!f.joinAt.empty()) plan.joins = parseJoinWaves(f.joinAt, "--join-at");
  plan.workerTimeoutSeconds =
      f.workerTimeoutSeconds.value_or(defaultLeaseSeconds(startingWorkers + plan.joinerCount()));
  plan.faults = parseFaults(f.faults);
  return plan;
}

std::vector<FaultInjection> parseFaults(const std::vector<std::string>& specs) {
  std::vector<FaultInjection> faults;
  for (const std::string& spec : specs) {
    const size_t first = spec.find(':');
    const size_t second = first == std::string::npos ? first : spec.find(':', first + 1);
    const auto fail = [&](const std::string& why) {
      throw InputError("--inject-fault '" + spec + "': " + why +
                       "; expected WORKER:PIXELS:crash|hang|corrupt, e.g. 1:500:crash");
    };
    if (second == std::string::npos) fail("three fields separated by ':' needed");
    const std::string_view text(spec);
    const auto worker = parseCount(text.substr(0, first), 1u << 20);
    if (!worker) fail("WORKER must be a worker number, 0 or more");
    const auto pixels = parseCount(text.substr(first + 1, second - first - 1), 1ull << 28);
    if (!pixels) fail("PIXELS must be a whole number of pixels from 0 to 2^28");
    const std::string_view kind = text.substr(second + 1);
    if (kind != "crash" && kind != "hang" && kind != "corrupt") {
      fail("the fault must be crash, hang or corrupt");
    }
    FaultInjection f;
    f.worker = static_cast<int>(*worker);
    f.afterPixels = *pixels;
    f.kind = kind == "crash"  ? FaultInjection::Kind::Crash
             : kind == "hang" ? FaultInjection::Kind::Hang
                              : FaultInjection::Kind::Corrupt;
    faults.push_back(f);
  }
  return faults;
}

}  // namespace prt::cli
