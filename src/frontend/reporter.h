// What a command tells a person on standard error besides errors: "wrote PATH" for every file it
// writes (every command, every file, and none it does not write), with what the file holds when
// that helps; and notes, such as a picture drawn smaller than asked. A quiet reporter says
// neither (`datomsim --quiet`, and Python, whose values say it all); errors and warnings of
// failure are always said, by whoever catches them.
#pragma once

#include <string>
#include <string_view>

namespace datomsim::frontend {

class Reporter {
 public:
  explicit Reporter(bool quiet = false) : quiet_(quiet) {}

  bool quiet() const { return quiet_; }
  // "wrote PATH", or "wrote PATH (HOLDS)".
  void reportWritten(const std::string& path, std::string_view holds = {}) const;
  // One line as it is.
  void note(std::string_view line) const;

 private:
  bool quiet_;
};

}  // namespace datomsim::frontend
