#include "verify/verify.h"

#include "verify/filter_order.h"
#include "verify/manufactured_flow.h"

namespace gridfree {

std::vector<OrderStudy> run_code_verification(const VerifyOptions& options) {
  std::vector<OrderStudy> studies;
  auto add = [&](OrderStudy s) {
    if (options.on_study) options.on_study(s);
    studies.push_back(std::move(s));
  };
  std::vector<Limiter> schemes = options.schemes;
  if (schemes.empty())
    for (const auto& info : limiters()) schemes.push_back(info.limiter);
  const std::vector<int> flow_grids = options.quick ? std::vector<int>{16, 32, 64}
                                                    : std::vector<int>{16, 32, 64, 128};
  for (Limiter scheme : schemes) add(manufactured_flow_order(scheme, flow_grids));
  const std::vector<int> filter_grids = options.quick ? std::vector<int>{16, 32, 64}
                                                      : std::vector<int>{16, 32, 64, 128};
  add(filter_order(filter_grids));
  return studies;
}

}  // namespace gridfree
