#include "frontend/json_stream.h"

#include <array>
#include <charconv>
#include <cmath>

namespace datomsim::frontend {

void JsonObjectStream::field(std::string_view key, const nlohmann::ordered_json& value) {
  open(key);
  buffer_.append(value.dump());
  flush();
}

namespace {

// The longest "[x,y,z,value]," a cell list writes with an integer value: four 20-character
// numbers and their punctuation.
constexpr size_t kLongestCell = 4 * 20 + 8;

char* writeInteger(char* at, int64_t value) {
  return std::to_chars(at, at + 20, value).ptr;
}

// ",[x,y,z" (no comma before the first of a list) into `at`.
char* writeCellStart(char* at, const geometry::Cell& cell, bool first) {
  if (!first) *at++ = ',';
  *at++ = '[';
  at = writeInteger(at, cell.x);
  *at++ = ',';
  at = writeInteger(at, cell.y);
  *at++ = ',';
  return writeInteger(at, cell.z);
}

}  // namespace

void JsonObjectStream::cells(std::string_view key, const std::vector<geometry::Cell>& list) {
  open(key);
  buffer_.push_back('[');
  for (size_t i = 0; i < list.size(); ++i) {
    std::array<char, kLongestCell> text;
    char* at = writeCellStart(text.data(), list[i], i == 0);
    *at++ = ']';
    buffer_.append(text.data(), at);
    flushIfFull();
  }
  buffer_.push_back(']');
  flush();
}

void JsonObjectStream::cellValues(std::string_view key,
                                  const std::vector<std::pair<geometry::Cell, int>>& list) {
  open(key);
  buffer_.push_back('[');
  for (size_t i = 0; i < list.size(); ++i) {
    std::array<char, kLongestCell> text;
    char* at = writeCellStart(text.data(), list[i].first, i == 0);
    *at++ = ',';
    at = writeInteger(at, list[i].second);
    *at++ = ']';
    buffer_.append(text.data(), at);
    flushIfFull();
  }
  buffer_.push_back(']');
  flush();
}

void JsonObjectStream::records(std::string_view key, size_t count,
                               const std::function<nlohmann::ordered_json(size_t)>& record) {
  open(key);
  buffer_.push_back('[');
  for (size_t i = 0; i < count; ++i) {
    if (i > 0) buffer_.push_back(',');
    const std::string text = record(i).dump();
    buffer_.append(text.data(), text.data() + text.size());
    flushIfFull();
  }
  buffer_.push_back(']');
  flush();
}

void JsonObjectStream::cellValues(std::string_view key,
                                  const std::vector<std::pair<geometry::Cell, double>>& list) {
  cellValues(key, [&](const CellValue& write) {
    for (const auto& [cell, value] : list) write(cell, value);
  });
}

void JsonObjectStream::cellValues(std::string_view key,
                                  const std::function<void(const CellValue&)>& source) {
  open(key);
  buffer_.push_back('[');
  bool first = true;
  source([&](const geometry::Cell& cell, double value) {
    std::array<char, kLongestCell> text;
    char* at = writeCellStart(text.data(), cell, first);
    first = false;
    *at++ = ',';
    if (isWhole(value)) {
      at = writeInteger(at, int64_t(value));
      *at++ = ']';
      buffer_.append(text.data(), at);
    } else {
      buffer_.append(text.data(), at);
      buffer_.append(nlohmann::ordered_json(value).dump());
      buffer_.push_back(']');
    }
    flushIfFull();
  });
  buffer_.push_back(']');
  flush();
}

void JsonObjectStream::close() {
  buffer_.append(std::string_view(first_ ? "{}\n" : "}\n"));
  flush();
}

void JsonObjectStream::open(std::string_view key) {
  buffer_.push_back(first_ ? '{' : ',');
  first_ = false;
  buffer_.append(nlohmann::ordered_json(key).dump());
  buffer_.push_back(':');
}

bool JsonObjectStream::isWhole(double value) {
  // The magnitude first: a cast of a value beyond int64_t is undefined.
  return std::abs(value) < 9e15 && value == double(int64_t(value));
}

void JsonObjectStream::flush() {
  emit_(std::string_view(buffer_.data(), buffer_.size()));
  buffer_.clear();
}

}  // namespace datomsim::frontend
