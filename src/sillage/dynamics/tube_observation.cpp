#include "sillage/dynamics/tube_observation.h"

#include "sillage/error.h"

namespace sillage::detail {

void check_observation_list(std::size_t n, const Interval& domain, const std::vector<TubeObservation>& obs,
                            const std::string& where) {
  if (obs.empty()) throw Error(where + ": needs at least one observation");
  for (std::size_t i = 0; i < obs.size(); ++i) {
    if (obs[i].z.size() != n) {
      throw DimensionError(where + ": observation " + std::to_string(i) + " has " + std::to_string(obs[i].z.size()) +
                           " components, the tube " + std::to_string(n));
    }
    if (!obs[i].t.intersects(domain)) {
      throw Error(where + ": the time " + obs[i].t.str() + " of observation " + std::to_string(i) +
                  " does not meet the time domain " + domain.str());
    }
    if (obs[i].ctc && obs[i].ctc->nb_vars() != n) {
      throw DimensionError(where + ": the contractor of observation " + std::to_string(i) + " (" +
                           obs[i].ctc->name() + ") acts on " + std::to_string(obs[i].ctc->nb_vars()) +
                           " variables, the tube has " + std::to_string(n));
    }
  }
}

}  // namespace sillage::detail
