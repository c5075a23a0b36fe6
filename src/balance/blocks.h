#pragma once
// Static blocks: c contiguous blocks in scan-line order, sizes differing by at most one (the
// larger ones first). Static: nothing moves afterwards. Lost workers: see StaticStrategy.

#include <cstdint>
#include <string>
#include <vector>

#include "balance/static_strategy.h"

namespace prt {

class BlocksStrategy final : public StaticStrategy {
 public:
  std::string name() const override { return "blocks"; }

 protected:
  std::vector<TaskSet> shares(const StartInfo& info) const override;
};

}  // namespace prt
