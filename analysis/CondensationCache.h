#pragma once
#include <cstddef>
#include <memory>
#include <vector>

struct cholmod_factor_struct;

namespace beamsolid {

// The last condensations of the process (CondensedSolver): a model rebuilt
// with the same constant part -- a parameter sweep that wipes and rebuilds the
// same soil mesh for each friction coefficient, say -- gets the factored A_II
// and the coupling A_BI A_II^-1 A_IB back instead of condensing again. An
// entry is reused only when everything the condensation depends on is equal,
// bit for bit: the partition, the three blocks' patterns and values. Holds
// the two most recent entries (a staged analysis alternates between two
// systems); BEAMSOLID_CONDENSE_CACHE=off switches it off.
class CondensationCache {
 public:
  // What a condensation depends on (CondensedSolver's blocks).
  struct Key {
    std::vector<char> interior;
    std::vector<int> iiStart, iiRow, ibStart, ibRow, biRow, biCol;
    std::vector<double> iiValues, ibValues, biValues;
    bool operator==(const Key& other) const;
  };

  static bool enabled();
  // A copy of the factor (allocated with the caller's CHOLMOD common) and the
  // coupling of an entry equal to `key`; false when there is none.
  static bool find(const Key& key, void* common, cholmod_factor_struct** factor, std::vector<double>& coupling);
  // Keeps copies; entries larger than kMaxBytes are not kept.
  static void store(const Key& key, const cholmod_factor_struct* factor, const std::vector<double>& coupling);
  // Entries found (for the tests and solver_info).
  static long hits();

 private:
  static constexpr std::size_t kMaxBytes = std::size_t(256) << 20;  // a copy costs memory and time too
};

}  // namespace beamsolid
