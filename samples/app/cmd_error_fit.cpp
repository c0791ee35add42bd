// `halfvec error-fit`: measures the error budget's table of shaders/common/error_budget.glsl
// (engine/eval error_fit.hpp) and writes it as engine/shading/src/error_table.cpp; the
// measurement is cached.
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "app/commands.hpp"
#include "halfvec/core/output_files.hpp"
#include "halfvec/eval/error_fit.hpp"

namespace hv::app {

namespace fs = std::filesystem;

namespace {

constexpr const char* kHelp = R"(Usage: halfvec error-fit [options]

Measures, per cell of the error budget's table (shaders/common/error_budget.glsl: roughness x
the light's angular radius x N.V x the light's angle from the reflection ray), how far the
representative-point sphere specular is from the reference, and writes the table the build
compiles (engine/shading/src/error_table.cpp). Deterministic; slices run in parallel; the
measurement is cached (keyed by the options and the table's layout).

Options:
  --out FILE      output (default engine/shading/src/error_table.cpp)
  --samples N     reference sample pairs per cell and side (default 16384)
  --seed N        first random seed (default 1)
  --threads N     threads (default: all cores)
  --cache DIR     cache folder (default out/cache; "" disables the cache)
  -h, --help      this text
)";

struct Options {
  std::string out = "engine/shading/src/error_table.cpp";
  std::string cache = "out/cache";
  eval::ErrorFitOptions fit;
};

Options parseArgs(const Args& args) {
  Options o;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--out") {
      o.out = optionValue(args, i);
    } else if (a == "--samples") {
      o.fit.samples = positiveInt(a, optionValue(args, i));
    } else if (a == "--seed") {
      o.fit.seed = uint64_t(positiveInt(a, optionValue(args, i)));
    } else if (a == "--threads") {
      o.fit.threads = positiveInt(a, optionValue(args, i));
    } else if (a == "--cache") {
      o.cache = optionValue(args, i);
    } else {
      throw UsageError{"unknown argument '" + a + "'"};
    }
  }
  if (o.out.empty()) throw UsageError{"--out needs a file name"};
  return o;
}

// The cache: a header naming the options and the layout, then the counts and the floats.
std::string cacheHeader(const eval::ErrorFitOptions& o, size_t cells) {
  return "halfvec error-fit v1 samples " + std::to_string(o.samples) + " seed " +
         std::to_string(o.seed) + " cells " + std::to_string(cells) + "\n";
}
bool loadCache(const fs::path& path, const eval::ErrorFitOptions& o, eval::ErrorFit& fit) {
  std::ifstream f(path, std::ios::binary);
  if (!f) return false;
  const std::string bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  const size_t cells = eval::fitErrorTableCells();
  const std::string head = cacheHeader(o, cells);
  if (bytes.size() != head.size() + 2 * sizeof(int) + cells * sizeof(float) ||
      bytes.compare(0, head.size(), head) != 0) {
    return false;
  }
  const char* p = bytes.data() + head.size();
  std::memcpy(&fit.measured, p, sizeof(int));
  std::memcpy(&fit.filled, p + sizeof(int), sizeof(int));
  fit.table.resize(cells);
  std::memcpy(fit.table.data(), p + 2 * sizeof(int), cells * sizeof(float));
  return true;
}
std::string cacheBytes(const eval::ErrorFit& fit, const eval::ErrorFitOptions& o) {
  std::string b = cacheHeader(o, fit.table.size());
  b.append(reinterpret_cast<const char*>(&fit.measured), sizeof(int));
  b.append(reinterpret_cast<const char*>(&fit.filled), sizeof(int));
  b.append(reinterpret_cast<const char*>(fit.table.data()), fit.table.size() * sizeof(float));
  return b;
}

}  // namespace

int cmdErrorFit(const Args& args) {
  for (const auto& a : args) {
    if (a == "--help" || a == "-h") {
      std::fputs(kHelp, stdout);
      return 0;
    }
  }
  Options o = parseArgs(args);
  OutputFiles outputs;
  const fs::path out_tmp = outputs.add(o.out);  // fails now if the folder is not writable
  const std::string command =
      recordedCommand("halfvec error-fit", args, {"--threads", "--cache", "--out"});
  const fs::path cache = o.cache.empty() ? fs::path() : fs::path(o.cache) / "error_fit.bin";
  eval::ErrorFit fit;
  const auto t0 = std::chrono::steady_clock::now();
  if (!cache.empty() && loadCache(cache, o.fit, fit)) {
    std::fprintf(stderr, "error-fit: cached measurement %s\n", cache.string().c_str());
  } else {
    o.fit.progress = [t0](int done, int total) {
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::fprintf(stderr, "error-fit: slice %d of %d, %.0f s, about %.0f s left\n", done, total, s,
                   s / done * (total - done));
    };
    fit = eval::fitErrorTable(o.fit);
    if (!cache.empty()) {
      fs::create_directories(cache.parent_path());
      writeFileAtomic(cache, cacheBytes(fit, o.fit));
    }
  }
  {
    std::ofstream f(out_tmp, std::ios::binary);
    f << eval::errorTableSource(fit, o.fit, command);
    if (!f) throw OutputError("cannot write " + out_tmp.string());
  }
  outputs.commit();
  std::printf("error-fit: wrote %s (%d measurements, %d cells filled)\n", o.out.c_str(),
              fit.measured, fit.filled);
  return 0;
}

}  // namespace hv::app
