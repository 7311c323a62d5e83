// Runs a fuzz target without libFuzzer (any compiler): every file of the corpus directories given
// on the command line, then seeded random mutations of them (byte flips, insertions, deletions,
// splices and repeats of chunks), so that the test suite replays the committed corpus and keeps
// exploring a little on every run.  Usage: replay [--mutations N] [--seed S] DIR...
// A finding aborts (or trips a sanitizer) and the input is written to fuzz-finding.bin first.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

using Bytes = std::vector<std::uint8_t>;

void run(const Bytes& input) {
  {  // kept when the target aborts, so the finding can be reproduced
    std::ofstream out("fuzz-finding.bin", std::ios::binary);
    out.write(reinterpret_cast<const char*>(input.data()),
              static_cast<std::streamsize>(input.size()));
  }
  LLVMFuzzerTestOneInput(input.data(), input.size());
}

Bytes mutate(const std::vector<Bytes>& corpus, std::mt19937_64& rng) {
  auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n)(rng); };
  Bytes b = corpus[pick(corpus.size() - 1)];
  // Bytes that matter to the two formats, besides random ones.
  static const std::string special = ",=#\"'[]\n\r\t .-+e0123456789:;\\";
  for (std::size_t k = 0, n = 1 + pick(4); k < n; ++k) {
    switch (pick(5)) {
      case 0:  // replace a byte
        if (!b.empty())
          b[pick(b.size() - 1)] =
              pick(1) ? static_cast<std::uint8_t>(pick(255))
                      : static_cast<std::uint8_t>(special[pick(special.size() - 1)]);
        break;
      case 1:  // insert a byte
        b.insert(b.begin() + static_cast<std::ptrdiff_t>(pick(b.size())),
                 static_cast<std::uint8_t>(special[pick(special.size() - 1)]));
        break;
      case 2:  // delete a chunk
        if (!b.empty()) {
          const auto at = pick(b.size() - 1);
          const auto len = std::min(b.size() - at, 1 + pick(8));
          b.erase(b.begin() + static_cast<std::ptrdiff_t>(at),
                  b.begin() + static_cast<std::ptrdiff_t>(at + len));
        }
        break;
      case 3: {  // splice in a chunk of another input
        const Bytes& other = corpus[pick(corpus.size() - 1)];
        if (other.empty()) break;
        const auto at = pick(other.size() - 1);
        const auto len = std::min(other.size() - at, 1 + pick(32));
        b.insert(b.begin() + static_cast<std::ptrdiff_t>(pick(b.size())),
                 other.begin() + static_cast<std::ptrdiff_t>(at),
                 other.begin() + static_cast<std::ptrdiff_t>(at + len));
        break;
      }
      default:  // repeat a chunk (long lines, many rows)
        if (!b.empty() && b.size() < 4096) {
          const auto at = pick(b.size() - 1);
          const Bytes chunk(b.begin() + static_cast<std::ptrdiff_t>(at),
                            b.begin() + static_cast<std::ptrdiff_t>(std::min(b.size(), at + 16)));
          for (std::size_t r = 0, reps = 1 + pick(20); r < reps; ++r)
            b.insert(b.end(), chunk.begin(), chunk.end());
        }
    }
  }
  return b;
}

}  // namespace

int main(int argc, char** argv) {
  long mutations = 0;
  std::uint64_t seed = 20261125;
  std::vector<Bytes> corpus;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--mutations" && i + 1 < argc) {
      mutations = std::stol(argv[++i]);
    } else if (arg == "--seed" && i + 1 < argc) {
      seed = std::stoull(argv[++i]);
    } else {
      for (const auto& entry : std::filesystem::directory_iterator(arg)) {
        std::ifstream in(entry.path(), std::ios::binary);
        corpus.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
      }
    }
  }
  if (corpus.empty()) {
    std::fprintf(stderr, "replay: no corpus files\n");
    return 1;
  }
  for (const auto& input : corpus) run(input);
  std::mt19937_64 rng(seed);
  for (long i = 0; i < mutations; ++i) run(mutate(corpus, rng));
  std::filesystem::remove("fuzz-finding.bin");
  std::printf("replay: %zu corpus inputs and %ld mutations (seed %llu), no finding\n",
              corpus.size(),
              mutations,
              static_cast<unsigned long long>(seed));
  return 0;
}
