// CPU time of building the contact tables of a profile pair (issue 9: under
// 1 s), median of repeats, with the benchmark S1002/UIC60 1:40 profiles.
// Usage: bench_contact_tables [repeats]   (from the repository root)
#include "cpu_timing.hpp"
#include <railstab/contact_geometry/contact_tables.hpp>
#include <railstab/profiles/profile_readers.hpp>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

using namespace railstab;

namespace {
using bench::cpu_seconds;
}  // namespace

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 7;
  const std::string dir = "cases/profiles/";
  std::vector<double> read_s, build_s;
  int slots = 0, nodes = 0;
  for (int k = 0; k < repeats; ++k) {
    const double t0 = cpu_seconds();
    const ProfilePair pair =
        make_profile_pair(read_simpack_profile(dir + "MBench_S1002_v3.prw", ProfileKind::wheel),
                          read_simpack_profile(dir + "MBench_UIC60_v3.prr", ProfileKind::rail),
                          ProfilePairParameters{});
    const double t1 = cpu_seconds();
    const ContactTable table = make_contact_table(pair);
    const double t2 = cpu_seconds();
    read_s.push_back(t1 - t0);
    build_s.push_back(t2 - t1);
    slots = table.slots();
    nodes = table.lateral_nodes() * table.roll_nodes();
  }
  auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  };
  std::printf("S1002/UIC60 1:40: %d slots x %d nodes (0.1 mm x 5 mrad)\n", slots, nodes);
  std::printf("read + place profiles: median %.4f s CPU\n", median(read_s));
  std::printf("build contact tables:  median %.4f s CPU (%d repeats, min %.4f, max %.4f)\n",
              median(build_s), repeats, *std::min_element(build_s.begin(), build_s.end()),
              *std::max_element(build_s.begin(), build_s.end()));
  return 0;
}
