#include "sillage/slam/slam_row.h"

#include <sstream>

namespace sillage {

std::string to_string(const SlamRow& r) {
  std::ostringstream os;
  os << "SlamRow(iteration=" << r.iteration << ", fast=" << (r.fast ? "True" : "False")
     << ", nb_detections=" << r.nb_detections << ", nb_proofs=" << r.nb_proofs << ", seconds=" << r.seconds
     << ", cumulated_seconds=" << r.cumulated_seconds << ", contraction_tf=" << r.contraction_tf
     << ", contraction_t0=" << r.contraction_t0 << ", nb_atoms_touched=" << r.nb_atoms_touched << ")";
  return os.str();
}

}  // namespace sillage
