// The driver for a harness built without libFuzzer (any compiler): runs each
// input file given (folders: every file in them, sorted), then -runs=N
// mutated copies of them (seeded: -seed=S), so CI replays the seed corpus and
// a bounded, reproducible sample around it under the sanitizers. Flags it
// does not know (libFuzzer's) are ignored, so one command line serves both.
// -last=FILE keeps each input in FILE before it runs: after a crash or a
// kill, FILE holds the input that did it.
//   fuzz_NAME [-runs=N] [-seed=S] [-last=FILE] FILE_OR_FOLDER...

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

std::vector<std::uint8_t> bytes_of(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// One to four of: flip a byte, cut the tail, insert a byte, repeat a run.
std::vector<std::uint8_t> mutate(std::vector<std::uint8_t> b, std::mt19937& rng) {
  const int edits = 1 + static_cast<int>(rng() % 4);
  for (int e = 0; e < edits; ++e) {
    const std::size_t n = b.size();
    switch (rng() % 4) {
      case 0:
        if (n > 0) b[rng() % n] ^= static_cast<std::uint8_t>(1 + rng() % 255);
        break;
      case 1:
        if (n > 0) b.resize(rng() % n);
        break;
      case 2:
        b.insert(b.begin() + static_cast<std::ptrdiff_t>(n > 0 ? rng() % (n + 1) : 0),
                 static_cast<std::uint8_t>(rng()));
        break;
      default:
        if (n > 1) {
          const std::size_t from = rng() % n, len = 1 + rng() % std::min<std::size_t>(64, n - from);
          const std::vector<std::uint8_t> run(b.begin() + static_cast<std::ptrdiff_t>(from),
                                              b.begin() + static_cast<std::ptrdiff_t>(from + len));
          b.insert(b.begin() + static_cast<std::ptrdiff_t>(rng() % (n + 1)), run.begin(), run.end());
        }
    }
  }
  return b;
}

}  // namespace

int main(int argc, char** argv) {
  long runs = 0;
  unsigned seed = 1;
  std::string last;
  std::vector<std::filesystem::path> inputs;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.rfind("-runs=", 0) == 0) {
      runs = std::stol(a.substr(6));
    } else if (a.rfind("-seed=", 0) == 0) {
      seed = static_cast<unsigned>(std::stoul(a.substr(6)));
    } else if (a.rfind("-last=", 0) == 0) {
      last = a.substr(6);
    } else if (!a.empty() && a[0] == '-') {
      continue;  // a libFuzzer flag
    } else if (std::filesystem::is_directory(a)) {
      std::vector<std::filesystem::path> here;
      for (const auto& e : std::filesystem::directory_iterator(a)) {
        if (e.is_regular_file()) here.push_back(e.path());
      }
      std::sort(here.begin(), here.end());
      inputs.insert(inputs.end(), here.begin(), here.end());
    } else {
      inputs.emplace_back(a);
    }
  }
  std::vector<std::vector<std::uint8_t>> corpus;
  for (const auto& p : inputs) corpus.push_back(bytes_of(p));
  auto run = [&](const std::vector<std::uint8_t>& b) {
    if (!last.empty())
      std::ofstream(last, std::ios::binary | std::ios::trunc)
          .write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size()));
    LLVMFuzzerTestOneInput(b.data(), b.size());
  };
  for (const auto& b : corpus) run(b);
  std::mt19937 rng(seed);
  for (long k = 0; k < runs && !corpus.empty(); ++k) run(mutate(corpus[rng() % corpus.size()], rng));
  std::printf("%s: %zu inputs replayed, %ld mutated runs (seed %u), no finding\n", argv[0], corpus.size(),
              corpus.empty() ? 0L : runs, seed);
  return 0;
}
