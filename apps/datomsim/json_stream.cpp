#include "json_stream.h"

#include <cmath>

namespace datomsim::app {

void JsonObjectStream::field(std::string_view key, const nlohmann::ordered_json& value) {
  open(key);
  buffer_.append(value.dump());
  flush();
}

void JsonObjectStream::cells(std::string_view key, const std::vector<geometry::Cell>& list) {
  open(key);
  buffer_.push_back('[');
  for (size_t i = 0; i < list.size(); ++i) {
    cellStart(list[i], i == 0);
    buffer_.push_back(']');
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
    cellStart(list[i].first, i == 0);
    buffer_.push_back(',');
    integer(list[i].second);
    buffer_.push_back(']');
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
    cellStart(cell, first);
    first = false;
    buffer_.push_back(',');
    number(value);
    buffer_.push_back(']');
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

void JsonObjectStream::cellStart(const geometry::Cell& cell, bool first) {
  buffer_.append(std::string_view(first ? "[" : ",["));
  integer(cell.x);
  buffer_.push_back(',');
  integer(cell.y);
  buffer_.push_back(',');
  integer(cell.z);
}

void JsonObjectStream::number(double value) {
  if (value == double(int64_t(value)) && std::abs(value) < 9e15) {
    integer(int64_t(value));
  } else {
    buffer_.append(nlohmann::ordered_json(value).dump());
  }
}

void JsonObjectStream::flush() {
  emit_(std::string_view(buffer_.data(), buffer_.size()));
  buffer_.clear();
}

}  // namespace datomsim::app
