// `halfvec ltc-fit`: fits the LTC table of shaders/common/ltc.glsl (engine/eval ltc_fit.hpp) and
// writes it as engine/shading/src/ltc_table.cpp; the fit is cached.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "app/commands.hpp"
#include "halfvec/core/output_files.hpp"
#include "halfvec/eval/ltc_fit.hpp"

namespace hv::app {

namespace fs = std::filesystem;

namespace {

constexpr const char* kHelp = R"(Usage: halfvec ltc-fit [options]

Fits the linearly transformed cosines of shaders/common/ltc.glsl to the engine's specular lobe
(GGX x height-correlated Smith x cos, F = 1) per cell of (roughness, N.V), and writes the table
the build compiles (engine/shading/src/ltc_table.cpp). Deterministic; rows run in parallel; the
fitted table is cached (keyed by the options and the fitting code's version).

Options:
  --out FILE          output (default engine/shading/src/ltc_table.cpp)
  --size N            cells per side (default 64; the engine reads HV_LTC_TABLE_SIZE)
  --fit-samples N     samples per dimension and strategy of the fit's error (default 32)
  --moment-samples N  samples per dimension of the integrated magnitudes (default 256)
  --power P           the fit minimizes integral |D_ltc - lobe|^P (default 3)
  --cap-weight W      plus W x the relative squared error of the LTC's integrals over caps of
                      3, 14 and 29 degrees on the lobe, the norm then relative to its value at
                      the start (default 100; 0: the norm alone; docs/lights.md measures both)
  --cap-max-nov X     the cap term only in the cells of N.V <= X (default 0.03: the last row,
                      N.V = 0.02; 1: every cell)
  --cap-glossy R,NOV  also in the cells of roughness <= R and N.V <= NOV (default 0.28,0.15:
                      the grazing views of glossy lobes; 0,0: none)
  --cap-samples N     lobe samples per dimension for the caps' integrals (default 128)
  --threads N         threads (default: all cores)
  --cache DIR         cache folder (default out/cache; "" disables the cache)
  --cell R,NOV        fit one cell at roughness R and N.V = NOV from the identity, print it
  -h, --help          this text
)";

struct Options {
  std::string out = "engine/shading/src/ltc_table.cpp";
  std::string cache = "out/cache";
  eval::LtcFitOptions fit;
  bool one_cell = false;
  float cell_roughness = 0.5f, cell_nov = 0.5f;
};

Options parseArgs(const Args& args) {
  Options o;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--out") {
      o.out = optionValue(args, i);
    } else if (a == "--size") {
      o.fit.size = positiveInt(a, optionValue(args, i));
      if (o.fit.size < 2) throw UsageError{"--size expects at least 2"};
    } else if (a == "--fit-samples") {
      o.fit.fit_samples = positiveInt(a, optionValue(args, i));
    } else if (a == "--moment-samples") {
      o.fit.moment_samples = positiveInt(a, optionValue(args, i));
    } else if (a == "--power") {
      o.fit.error_power = numberInRange(a, optionValue(args, i), 1.0, 8.0);
    } else if (a == "--cap-weight") {
      o.fit.cap_weight = numberInRange(a, optionValue(args, i), 0.0, 1e6);
    } else if (a == "--cap-max-nov") {
      o.fit.cap_max_nov = numberInRange(a, optionValue(args, i), 0.0, 1.0);
    } else if (a == "--cap-glossy") {
      const std::string v = optionValue(args, i);
      double r = 0.0, nov = 0.0;
      char tail = 0;
      if (std::sscanf(v.c_str(), "%lf,%lf%c", &r, &nov, &tail) != 2 || !(r >= 0.0 && r <= 1.0) ||
          !(nov >= 0.0 && nov <= 1.0)) {
        throw UsageError{"--cap-glossy expects R,NOV with both in [0, 1], got '" + v + "'"};
      }
      o.fit.cap_glossy_roughness = r;
      o.fit.cap_glossy_nov = nov;
    } else if (a == "--cap-samples") {
      o.fit.cap_samples = positiveInt(a, optionValue(args, i));
    } else if (a == "--threads") {
      o.fit.threads = positiveInt(a, optionValue(args, i));
    } else if (a == "--cache") {
      o.cache = optionValue(args, i);
    } else if (a == "--cell") {
      const std::string v = optionValue(args, i);
      if (std::sscanf(v.c_str(), "%f,%f", &o.cell_roughness, &o.cell_nov) != 2 ||
          !(o.cell_roughness >= 0.0f && o.cell_roughness <= 1.0f && o.cell_nov >= 0.0f &&
            o.cell_nov <= 1.0f)) {
        throw UsageError{"--cell expects R,NOV in [0, 1], got '" + v + "'"};
      }
      o.one_cell = true;
    } else {
      throw UsageError{"unknown argument '" + a + "'"};
    }
  }
  if (o.out.empty()) throw UsageError{"--out needs a file name"};
  return o;
}

int fitOneCell(const Options& o) {
  const auto t0 = std::chrono::steady_clock::now();
  const eval::LtcCell c = eval::fitLtcCell(o.cell_roughness, o.cell_nov, {}, o.fit);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf(
      "roughness %g, N.V %g: a_x/alpha %.6g, a_y/alpha %.6g, s %.6g, d_x %.6g, n_f %.6g, "
      "n_fresnel %.6g, L1 distance %.5f, %d iterations, %.2f s\n",
      o.cell_roughness, o.cell_nov, c.params.ax, c.params.ay, c.params.sk, c.params.dx, c.norm,
      c.fresnel, c.error, c.iterations, s);
  return 0;
}

}  // namespace

int cmdLtcFit(const Args& args) {
  for (const auto& a : args) {
    if (a == "--help" || a == "-h") {
      std::fputs(kHelp, stdout);
      return 0;
    }
  }
  Options o = parseArgs(args);
  if (o.one_cell) return fitOneCell(o);
  OutputFiles outputs;
  const fs::path out_tmp = outputs.add(o.out);  // fails now if the folder is not writable
  const std::string command = recordedCommand("halfvec ltc-fit", args, {"--threads", "--cache"});
  const fs::path cache = o.cache.empty() ? fs::path() : fs::path(o.cache) / "ltc_fit.bin";
  eval::LtcTable table;
  const auto t0 = std::chrono::steady_clock::now();
  if (!cache.empty() && eval::loadLtcCache(cache.string(), o.fit, table)) {
    std::fprintf(stderr, "ltc-fit: cached fit %s\n", cache.string().c_str());
  } else {
    o.fit.progress = [t0](int done, int total) {
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::fprintf(stderr, "ltc-fit: row %d of %d, %.0f s, about %.0f s left\n", done, total, s,
                   s / done * (total - done));
    };
    table = eval::fitLtcTable(o.fit);
    if (!cache.empty()) {
      fs::create_directories(cache.parent_path());
      writeFileAtomic(cache, eval::ltcCacheBytes(table, o.fit));
    }
  }
  {
    std::ofstream f(out_tmp, std::ios::binary);
    f << eval::ltcTableSource(table, o.fit, command);
    if (!f) throw OutputError("cannot write " + out_tmp.string());
  }
  outputs.commit();
  std::printf("ltc-fit: wrote %s\n", o.out.c_str());
  return 0;
}

}  // namespace hv::app
