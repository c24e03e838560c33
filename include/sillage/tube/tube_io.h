#pragma once
// Binary serialization of tubes and tube vectors.
//
// Format (little endian): magic "SLGTUBE\0" (8 bytes), format version
// (uint32, currently 1), kind (uint32: 1 = Tube, 2 = TubeVector), number of
// time points N+1 (uint64) and the time points (float64), number of
// components n (uint64), then for each component its N slices and N+1 gates
// as (lb, ub) float64 pairs (the empty set is (+inf, -inf)).
//
// Loading checks everything: magic, version, kind, sizes, time points (finite
// and increasing: an error gives the first bad one, its byte and its value),
// bound pairs; a truncated or foreign file throws Error saying what and at
// which byte offset, and naming the file. A gate disjoint from a neighbouring
// slice is loaded as saved (a tube that holds no trajectory, as
// Tube(td, slices, gates) takes it). A file holds one object: trailing bytes
// are an Error (giving the byte where they start), a directory, a device, an
// unreadable path or a file larger than max_file_bytes() (read_file.h: 2 GiB
// by default) too. A stream is read up to the end of the object only. When a
// TDomain is passed, the stored time points must equal its own
// (DimensionError otherwise, naming the first that differs) and the result is
// attached to it; otherwise a new TDomain is created.
#include <iosfwd>
#include <memory>
#include <string>

#include "sillage/tube/tube.h"
#include "sillage/tube/tube_vector.h"

namespace sillage {

inline constexpr std::uint32_t kTubeFileVersion = 1;

void save(const Tube& x, std::ostream& os);
void save(const TubeVector& x, std::ostream& os);
void save(const Tube& x, const std::string& path);
void save(const TubeVector& x, const std::string& path);

Tube load_tube(std::istream& is, std::shared_ptr<TDomain> td = nullptr);
TubeVector load_tube_vector(std::istream& is, std::shared_ptr<TDomain> td = nullptr);
// Reads a Tube written by save_tube, on tdomain if given (same time points).
Tube load_tube(const std::string& path, std::shared_ptr<TDomain> td = nullptr);
// Reads a TubeVector written by save_tube, on tdomain if given.
TubeVector load_tube_vector(const std::string& path, std::shared_ptr<TDomain> td = nullptr);

}  // namespace sillage
