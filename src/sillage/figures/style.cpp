#include "sillage/figures/style.h"

namespace sillage {

Style paving_style(PavingTag tag) {
  switch (tag) {
    case PavingTag::Inner: return {"#9bd49b", "#2f7d32", 0.5, 1.0, "inner"};
    case PavingTag::Boundary: return {"#ffe680", "#b89500", 0.5, 1.0, "boundary"};
    case PavingTag::Outside: return {"#a9cdf2", "#2a6aa8", 0.5, 1.0, "outside"};
  }
  return {};
}

}  // namespace sillage
