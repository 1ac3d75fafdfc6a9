#include "frontend/run_json.h"

#include <nlohmann/json.hpp>

#include "frontend/json_stream.h"
#include "sim/statistics.h"

namespace datomsim::frontend {

namespace {

void streamRunJson(const algorithms::ProgramInfo& info, const experiment::RunResult& result,
                   const std::map<std::string, std::string>& parameters,
                   JsonObjectStream::Emit emit) {
  const sim::Statistics& statistics = result.statistics;
  auto seconds = [](Time t) { return double(t) / kSecond; };
  JsonObjectStream out(std::move(emit));
  out.field("program", info.name);
  if (result.reshape) {
    out.field("success", result.reshape->success);
    if (!result.reshape->success) out.field("reason", result.reshape->reason);
    out.cells("final", result.reshape->final);
    out.cells("missing", result.reshape->missing);
    out.cells("extra", result.reshape->extra);
  } else if (info.entry) {
    // A public-API program: its parameters, then what its modules reported, key by key.
    nlohmann::ordered_json given = nlohmann::ordered_json::object();
    for (const auto& [name, value] : parameters) given[name] = value;
    out.field("parameters", given);
    out.field("stopped_at_limit", result.stoppedAtLimit);
    if (result.reports) {
      for (const std::string& key : result.reports->keys()) {
        out.cellValues(key, [&](const JsonObjectStream::CellValue& write) {
          result.reports->forEach(key, write);
        });
      }
    }
  } else if (!info.needsGoal) {
    nlohmann::ordered_json walkers = nlohmann::ordered_json::array();
    for (const algorithms::WalkerOutcome& walker : result.walkers) {
      walkers.push_back({{"id", walker.id.value},
                         {"steps", walker.steps},
                         {"refusals", walker.refusals},
                         {"finished", walker.finished},
                         {"failure", walker.failure ? nlohmann::ordered_json(*walker.failure)
                                                    : nlohmann::ordered_json()}});
    }
    out.field("walkers", walkers);
  } else if (!info.mobileWalks) {
    // Exactly as `reach` writes its distances.
    out.cellValues("distances", result.distances);
  } else {
    out.cells("path", result.path);
    out.field("arrived", result.arrived.value_or(false));
  }
  if (result.failure && !result.reshape) out.field("reason", *result.failure);
  out.field("motions", statistics.motions);
  out.field("makespan_s", seconds(statistics.lastMotionEnd));
  out.field("messages", statistics.messages());
  out.field("max_concurrent_motions", statistics.maxConcurrentMotions);
  out.field("mean_concurrent_motions", statistics.meanConcurrentMotions());
  nlohmann::ordered_json refusals = nlohmann::ordered_json::object();
  for (const auto& [reason, count] : statistics.refusalsByReason) refusals[reason] = count;
  out.field("refusals_by_reason", refusals);
  out.field("reservation_wait_s", seconds(statistics.reservationWait));
  nlohmann::ordered_json messages = nlohmann::ordered_json::object();
  for (const auto& [type, count] : statistics.messagesByType) messages[type] = count;
  out.field("messages_by_type", messages);
  out.field("events", statistics.events());
  nlohmann::ordered_json byKind = nlohmann::ordered_json::object();
  for (int kind = 0; kind < sim::kEventKindCount; ++kind) {
    byKind[sim::toString(sim::EventKind(kind))] = statistics.eventsByKind[size_t(kind)];
  }
  out.field("events_by_kind", byKind);
  out.field("deformations", statistics.deformations);
  out.field("sim_time_s", seconds(statistics.simulatedTime));
  // Wall time stays out of the JSON, which is the same for the same inputs; --stats prints it.
  out.close();
}

}  // namespace

std::string runJson(const algorithms::ProgramInfo& info, const experiment::RunResult& result,
                    const std::map<std::string, std::string>& parameters) {
  std::string text;
  streamRunJson(info, result, parameters, [&](std::string_view piece) { text += piece; });
  return text;
}

Status writeRunJson(const algorithms::ProgramInfo& info, const experiment::RunResult& result,
                    const std::map<std::string, std::string>& parameters, std::FILE* file) {
  FileEmitter emitter{file};
  streamRunJson(info, result, parameters, emitter.emit());
  return emitter.status("the result");
}

}  // namespace datomsim::frontend
