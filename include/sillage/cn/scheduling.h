#pragma once
// The order in which a ContractorNetwork runs the contractors of a round
// (ContractorNetwork::set_scheduling).
namespace sillage {

// Fifo: in the order they were woken (round 1: the order of add()).
// Priority: by expected contraction over cost, the most promising first: the
// expected contraction of a contractor is the share of its atoms it shrank
// (beyond the wake ratio) the last time it ran (1 before its first run), its
// cost the number of atoms it has to look at (those that changed since it
// last ran, 1 at least). Every round still runs each woken contractor once,
// so the propagation reaches the same fixed point (with ratio 0, the greatest
// common fixed point of monotone contractors); only the order within a round,
// hence which contractions a later contractor already sees, changes.
enum class Scheduling { Fifo, Priority };

}  // namespace sillage
