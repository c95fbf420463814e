#pragma once
// CPU-time measurement shared by the benchmarks (analysis/bench_*.cpp). CPU
// clocks, not wall clocks: these machines are shared and loaded, and a
// process's CPU time is what it costs whatever else runs.
#include <algorithm>
#include <ctime>
#include <functional>
#include <vector>

namespace railstab::bench {

// CPU seconds of this process so far.
inline double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// CPU seconds per call: `batches` batches, each repeating the call until it
// has lasted at least batch_s; the median of the batch means (robust to a
// batch slowed by another process).
inline double median_of_batches(const std::function<void()>& call, int batches = 5,
                                double batch_s = 0.2) {
  std::vector<double> means;
  for (int batch = 0; batch < batches; ++batch) {
    long calls = 0;
    const double start = cpu_seconds();
    double elapsed = 0.0;
    do {
      call();
      ++calls;
      elapsed = cpu_seconds() - start;
    } while (elapsed < batch_s);
    means.push_back(elapsed / double(calls));
  }
  std::sort(means.begin(), means.end());
  return means[means.size() / 2];
}

}  // namespace railstab::bench
