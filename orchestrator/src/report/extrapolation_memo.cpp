// SPDX-License-Identifier: GPL-3.0-or-later
// Extrapolations remembered between report writes (see extrapolation_memo.h).
#include "report/extrapolation_memo.h"

#include <cstring>
#include <utility>

namespace gridfree {

namespace {

// The exact bits of h and f: equal keys mean equal inputs.
std::string input_key(const std::vector<double>& h, const std::vector<double>& f) {
  std::string key(sizeof(double) * (h.size() + f.size()) + 1, '\0');
  std::memcpy(key.data(), h.data(), sizeof(double) * h.size());
  key[sizeof(double) * h.size()] = '|';
  std::memcpy(key.data() + sizeof(double) * h.size() + 1, f.data(), sizeof(double) * f.size());
  return key;
}

}  // namespace

Extrapolator ExtrapolationMemo::wrap(Extrapolator inner) {
  return [this, inner = std::move(inner)](const std::vector<double>& h, const std::vector<double>& f) {
    std::string key = input_key(h, f);
    if (const auto it = current_.find(key); it != current_.end()) {
      ++hits_;
      return nlohmann::json::from_cbor(it->second);
    }
    if (auto it = previous_.find(key); it != previous_.end()) {
      ++hits_;
      const auto& kept = current_.emplace(std::move(key), std::move(it->second)).first->second;
      previous_.erase(it);
      return nlohmann::json::from_cbor(kept);
    }
    nlohmann::json result = inner(h, f);
    current_.emplace(std::move(key), nlohmann::json::to_cbor(result));
    return result;
  };
}

void ExtrapolationMemo::end_write() {
  previous_ = std::move(current_);
  current_.clear();
}

}  // namespace gridfree
