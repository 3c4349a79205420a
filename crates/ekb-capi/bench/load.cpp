// Loading through the C++ API in process (scripts/bench-loader.sh): the time of
// ekb::KnowledgeBase::open on one file, the best and the median of REPEATS runs, and the
// process's peak resident memory before the first load and after the runs.
//
// Usage: ekb-load-benchmark FILE [REPEATS]
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "ekb.hpp"

static long peakKilobytes() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss;
}

int main(int argc, char **argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: ekb-load-benchmark FILE [REPEATS]\n");
        return 2;
    }
    int repeats = argc > 2 ? std::atoi(argv[2]) : 10;
    long before = peakKilobytes();
    std::vector<double> seconds;
    std::size_t locations = 0;
    for (int run = 0; run < repeats; ++run) {
        auto start = std::chrono::steady_clock::now();
        ekb::KnowledgeBase kb = ekb::KnowledgeBase::open(argv[1]);
        locations = kb.size();
        seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    std::sort(seconds.begin(), seconds.end());
    std::printf("%s\t%zu locations\tbest %.3f ms\tmedian %.3f ms\tpeak RSS %ld kB before, %ld kB after\n", argv[1],
                locations, seconds.front() * 1e3, seconds[seconds.size() / 2] * 1e3, before, peakKilobytes());
    return 0;
}
