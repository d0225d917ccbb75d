#pragma once
/// @file
/// The output of high-level culling: a candidate triangle pair (CTP).

#include "tailor/geometry/types.hpp"

namespace tailor {

/// A candidate triangle pair (CTP) of face ids, `first < second`.
struct TrianglePair {
  ///@{
  /// Face ids (-1 when unset).
  Index first = -1, second = -1;
  ///@}
};

}  // namespace tailor
