#pragma once
// The Manchester Contact Benchmark pair of the shipped cases: new S1002 on
// UIC60 1:40 (cases/profiles/), placed with the default parameters.
#include <railstab/profiles/profile_pair.hpp>
#include <railstab/profiles/profile_readers.hpp>

#include <string>

namespace railstab::test {

inline ProfilePair benchmark_profile_pair() {
  const std::string dir = std::string(RAILSTAB_CASES_DIR) + "/profiles/";
  return make_profile_pair(read_simpack_profile(dir + "MBench_S1002_v3.prw", ProfileKind::wheel),
                           read_simpack_profile(dir + "MBench_UIC60_v3.prr", ProfileKind::rail),
                           ProfilePairParameters{});
}

}  // namespace railstab::test
