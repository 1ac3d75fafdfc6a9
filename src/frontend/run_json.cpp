#include "frontend/run_json.h"

#include <nlohmann/json.hpp>

#include <type_traits>
#include <variant>

#include "frontend/energy_json.h"
#include "frontend/json_stream.h"
#include "sim/statistics.h"

namespace datomsim::frontend {

namespace {

nlohmann::ordered_json jsonOf(const algorithms::RunReport::Scalar& scalar) {
  return std::visit(
      [](const auto& value) -> nlohmann::ordered_json {
        if constexpr (std::is_same_v<std::decay_t<decltype(value)>, std::monostate>) {
          return nullptr;
        } else {
          return value;
        }
      },
      scalar);
}

nlohmann::ordered_json jsonOf(const algorithms::RunReport::Record& record) {
  nlohmann::ordered_json object = nlohmann::ordered_json::object();
  for (const auto& [key, value] : record) object[key] = jsonOf(value);
  return object;
}

// A program's section, by the kind of its value.
void writeSection(JsonObjectStream& out, const algorithms::RunReport::Section& section) {
  using Report = algorithms::RunReport;
  const std::string& key = section.key;
  std::visit(
      [&](const auto& value) {
        using Value = std::decay_t<decltype(value)>;
        if constexpr (std::is_same_v<Value, bool>) {
          out.field(key, value);
        } else if constexpr (std::is_same_v<Value, Report::Record>) {
          out.field(key, jsonOf(value));
        } else if constexpr (std::is_same_v<Value, std::vector<Report::Record>>) {
          nlohmann::ordered_json list = nlohmann::ordered_json::array();
          for (const Report::Record& record : value) list.push_back(jsonOf(record));
          out.field(key, list);
        } else if constexpr (std::is_same_v<Value, std::vector<geometry::Cell>>) {
          out.cells(key, value);
        } else if constexpr (std::is_same_v<Value, Report::CellInts>) {
          out.cellValues(key, value);
        } else {
          static_assert(std::is_same_v<Value, Report::Streamed>);
          out.cellValues(key, [&](const JsonObjectStream::CellValue& write) { value(write); });
        }
      },
      section.value);
}

// The program's name; what the watch of a target found; the program's own sections; why the run
// failed; the statistics.
void streamRunJson(std::string_view program, const experiment::RunResult& result,
                   JsonObjectStream::Emit emit) {
  const sim::Statistics& statistics = result.statistics;
  auto seconds = [](Time t) { return double(t) / kSecond; };
  JsonObjectStream out(std::move(emit));
  out.field("program", program);
  if (result.reshape) {
    out.field("success", result.reshape->success);
    if (!result.reshape->success) out.field("reason", result.reshape->reason);
    out.cells("final", result.reshape->final);
    out.cells("missing", result.reshape->missing);
    out.cells("extra", result.reshape->extra);
  }
  for (const algorithms::RunReport::Section& section : result.report.sections()) {
    writeSection(out, section);
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
  if (const auto& checks = result.loadChecks) {
    // Written only with gravity on: a run without keeps its bytes.
    nlohmann::ordered_json gravity = {{"changes_judged", checks->changes},
                                      {"refused", checks->refused},
                                      {"pieces_solved", checks->solves},
                                      {"modules_solved", checks->modules},
                                      {"largest_piece", checks->largest}};
    out.field("gravity", gravity);
  }
  // Written only with actuators: a run without keeps its bytes.
  if (result.energy) out.field("energy", energyJson(*result.energy, statistics.motions));
  // Wall time stays out of the JSON, which is the same for the same inputs; --stats prints it.
  out.close();
}

}  // namespace

std::string runJson(std::string_view program, const experiment::RunResult& result) {
  std::string text;
  streamRunJson(program, result, [&](std::string_view piece) { text += piece; });
  return text;
}

Status writeRunJson(std::string_view program, const experiment::RunResult& result,
                    std::FILE* file) {
  FileEmitter emitter{file};
  streamRunJson(program, result, emitter.emit());
  return emitter.status("the result");
}

}  // namespace datomsim::frontend
