#include "isovdb/volume/mask_rule.h"

#include <sstream>

namespace isovdb::volume {

std::string MaskRule::describe() const {
  std::ostringstream out;
  if (labels.empty()) {
    out << "value > " << threshold;
  } else {
    out << "label in {";
    for (std::size_t i = 0; i < labels.size(); ++i) out << (i ? "," : "") << labels[i];
    out << "}";
  }
  return out.str();
}

}  // namespace isovdb::volume
