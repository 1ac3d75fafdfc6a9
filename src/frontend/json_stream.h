// A JSON object written field by field as it is made: small values as nlohmann prints them, and
// the long lists of cells (millions for a large scene) formatted straight into a small buffer that
// is handed on every few kilobytes, so that no document is ever held whole.
#pragma once

#include <fmt/format.h>

#include <cstdint>
#include <cstdio>
#include <functional>
#include <nlohmann/json.hpp>
#include <string_view>
#include <utility>
#include <vector>

#include "datomsim/result.h"
#include "geometry/cell.h"

namespace datomsim::frontend {

class JsonObjectStream {
 public:
  using Emit = std::function<void(std::string_view)>;

  explicit JsonObjectStream(Emit emit) : emit_(std::move(emit)) {}

  void field(std::string_view key, const nlohmann::ordered_json& value);
  // [[x,y,z], ...]
  void cells(std::string_view key, const std::vector<geometry::Cell>& list);
  // [[x,y,z,value], ...]; whole numbers print as integers, others as nlohmann prints them.
  void cellValues(std::string_view key, const std::vector<std::pair<geometry::Cell, int>>& list);
  void cellValues(std::string_view key, const std::vector<std::pair<geometry::Cell, double>>& list);
  // The same from a source that calls its argument once per cell, in order: nothing is gathered.
  using CellValue = std::function<void(const geometry::Cell&, double)>;
  void cellValues(std::string_view key, const std::function<void(const CellValue&)>& source);
  // A list of `count` values made one at a time by `record` (small objects: each is printed and
  // dropped before the next is made).
  void records(std::string_view key, size_t count,
               const std::function<nlohmann::ordered_json(size_t)>& record);
  // Ends the object and the line.
  void close();

 private:
  void open(std::string_view key);
  // Whether a value prints as an integer; others print as nlohmann prints them.
  static bool isWhole(double value);
  void flushIfFull() {
    if (buffer_.size() >= size_t{1} << 16) flush();
  }
  void flush();

  Emit emit_;
  fmt::memory_buffer buffer_;
  bool first_ = true;
};

// An emitter writing to an open file, and whether every write went through.
struct FileEmitter {
  std::FILE* file;
  bool written = true;
  JsonObjectStream::Emit emit() {
    return [this](std::string_view piece) {
      written = written && std::fwrite(piece.data(), 1, piece.size(), file) == piece.size();
    };
  }
  Status status(std::string_view what) const {
    if (!written) return Error{"cannot write " + std::string(what)};
    return Ok{};
  }
};

}  // namespace datomsim::frontend
