// SPDX-License-Identifier: GPL-3.0-or-later
// Problems with user input, each tied to where it was found.
//
// A Problem's `where` is a JSON pointer ("/case/domain_dp/1"), a file
// position ("particles.csv:17"), or a CLI option ("--threads"). Validation
// collects every problem it can find before throwing one InputError, so
// users fix everything in one pass.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace gridfree {

struct Problem {
  std::string where;   // JSON pointer, file:line, or option name
  std::string reason;  // why it is wrong, in words a user understands
};

class InputError : public std::runtime_error {
 public:
  explicit InputError(std::vector<Problem> problems);
  InputError(std::string where, std::string reason);

  const std::vector<Problem>& problems() const { return problems_; }

 private:
  std::vector<Problem> problems_;
};

// "where: reason" lines, one per problem.
std::string format_problems(const std::vector<Problem>& problems);

// The same lines each starting "error: ", as both executables print an
// InputError (docs/INTERFACE.md "Error messages").
std::string error_lines(const InputError& e);

// Collects problems; throws one InputError at the end if any were found.
class ProblemList {
 public:
  void add(std::string where, std::string reason) {
    problems_.push_back({std::move(where), std::move(reason)});
  }
  void append(const std::vector<Problem>& more) {
    problems_.insert(problems_.end(), more.begin(), more.end());
  }
  // Adds the problem unless one is already reported at `where`.
  void add_once(const std::string& where, std::string reason) {
    if (!has(where)) add(where, std::move(reason));
  }
  bool has(const std::string& where) const {
    for (const auto& p : problems_)
      if (p.where == where) return true;
    return false;
  }
  bool empty() const { return problems_.empty(); }
  const std::vector<Problem>& problems() const { return problems_; }
  void throw_if_any() const {
    if (!problems_.empty()) throw InputError(problems_);
  }

 private:
  std::vector<Problem> problems_;
};

}  // namespace gridfree
