// Every command on random command lines of valid and invalid values, run as
// a separate process as a user would run it: it exits 0 or with a documented
// error code (never a signal, never a hang), every failure says why on
// stderr, and a failed command leaves no file behind.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "cli/app.h"

namespace aapat {
namespace {

namespace fs = std::filesystem;

struct Outcome {
  bool exited = false;
  int code = -1;
  int signal = 0;
  bool timed_out = false;
  std::string err;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs the aapat binary in `dir` with a wall-clock limit.
Outcome run_process(const std::vector<std::string>& args, const fs::path& dir, double seconds) {
  const fs::path err_file = dir / ".stderr", out_file = dir / ".stdout";
  const pid_t pid = fork();
  if (pid == 0) {
    if (chdir(dir.c_str()) != 0) _exit(125);
    const int out = open(out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = open(err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(out, 1);
    dup2(err, 2);
    const int null = open("/dev/null", O_RDONLY);
    dup2(null, 0);
    std::vector<char*> argv;
    std::string binary = AAPAT_BINARY;
    argv.push_back(binary.data());
    std::vector<std::string> copy = args;
    for (auto& a : copy) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(binary.c_str(), argv.data());
    _exit(126);
  }
  Outcome o;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  int status = 0;
  while (waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      o.timed_out = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (!o.timed_out) {
    o.exited = WIFEXITED(status);
    o.code = o.exited ? WEXITSTATUS(status) : -1;
    o.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  }
  o.err = slurp(err_file);
  fs::remove(err_file);
  fs::remove(out_file);
  return o;
}

std::set<std::string> listing(const fs::path& dir) {
  std::set<std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    files.insert(fs::relative(e.path(), dir).string());
  return files;
}

// The folder every run works in, with the input files the specs name.
fs::path workspace() {
  static const fs::path dir = [] {
    const fs::path d = fs::path(::testing::TempDir()) / "aapat_command_property";
    fs::remove_all(d);
    fs::create_directories(d / "folder.json");
    fs::create_directories(d / "folder");
    std::ofstream(d / "bad.json") << "{\"format\": \"aapat-pattern\", \"version\": 1, \"name\": 7}";
    std::ofstream(d / "nan.json") << "{\"sets\": [[NaN, 0]]}";
    std::ofstream(d / "huge.json") << "{\"format\": \"aapat-scene\", \"shapes\": [{\"circle\": "
                                      "[1e999, 0], \"radius\": 1}]}";
    std::ofstream(d / "scene.json")
        << "{\"format\": \"aapat-scene\", \"background\": 0.2, \"shapes\": [{\"polygon\": [[2, 2], "
           "[14, 3], [8, 13]], \"grey\": 0.9}, {\"circle\": [5, 9], \"radius\": 3}]}";
    std::ofstream(d / "acuity.csv") << "0,1\n45,2\n90,1\n135,2\n";
    std::ofstream(d / "bad.csv") << "0,1,2\nx,y\n";
    std::ofstream(d / "points.csv") << "0.1,0.2\n0.5,0.5\n0.9,0.3\n";
    std::ofstream(d / "outside.csv") << "0.1,0.2\n1.5,0.5\n";
    std::ofstream(d / "invalid-utf8.json") << "{\"name\": \"\xff\xfe\"}";
    const char* show[] = {"aapat", "show", "flipquad", "-o", "good.json"};
    std::ostringstream out, err;
    const fs::path here = fs::current_path();
    fs::current_path(d);
    run_aapat(5, show, out, err);
    fs::current_path(here);
    return d;
  }();
  return dir;
}

const std::vector<std::string> kPatterns = {
    "centroid", "rgss",     "flipquad",    "fliptri",          "quincunx",     "hasselgren-c",
    "msaa-4",   "nosuch",   "folder.json", "bad.json",         "missing.json", "good.json",
    "nan.json", "grid-3x3", "grid-0x0",    "invalid-utf8.json"};
const std::vector<std::string> kFilters = {
    "mitchell",    "gaussian:sigma=0.3",  "gaussian:sigma=1e-5",
    "box:width=0", "lanczos:lobes=2.5",   "tent:radius=nan",
    "nosuch",      "mitchell:b=1,c",      "keys:a=-1/2",
    "blinn",       "gaussian:sigma=0.05", "box:width=1e308"};
const std::vector<std::string> kAcuity = {"laine-aila",
                                          "uniform:step=5",
                                          "uniform:step=1e-9",
                                          "linear:step=10",
                                          "uniform:step=1,weight=1e308",
                                          "acuity.csv",
                                          "bad.csv",
                                          "folder",
                                          "uniform:weight=2",
                                          "uniform:step=nan"};
const std::vector<std::string> kNorms = {"inf", "2", "1000", "0.5", "nan", "-1", "abc", "1e9"};
const std::vector<std::string> kSeeds = {
    "1", "0", "-1", "18446744073709551615", "18446744073709551616", "1.5", "x"};
const std::vector<std::string> kFamilies = {"P(1,1,2)", "P(4,1+,1.25)", "P(4,1+,2)",
                                            "P(1,1,0)", "P(3,1,2)",     "garbage",
                                            "P(4,4,2)", "P(1,1,1e9)",   "P(1,1+,2)"};
const std::vector<std::string> kGenerators = {"jittered",         "halton",
                                              "poisson",          "best-candidate",
                                              "n-queens",         "regular",
                                              "poisson:radius=2", "halton:b1=1",
                                              "nosuch",           "points.csv",
                                              "outside.csv",      "good.json",
                                              "bad.csv",          "semi-jittered:amount=3"};
const std::vector<std::string> kCounts = {"1", "4", "9", "16", "0", "-3", "7", "1e9", "nan"};
const std::vector<std::string> kScenes = {
    "checkerboard",       "circles:count=5", "spiral",    "disc",   "sliver",
    "zoneplate:k=1e308",  "scene.json",      "huge.json", "nosuch", "folder.json",
    "halfplane:angle=nan"};
const std::vector<std::string> kSizes = {"16x16", "8x12", "0x0", "abc", "16", "100000x100000"};

// Uniform choices: rapidcheck's generators grow with the test's size, which
// would favour the first commands and values.
int uniform(int lo, int hi_exclusive) {
  return *rc::gen::resize(rc::kNominalSize, rc::gen::inRange(lo, hi_exclusive));
}
rc::Gen<std::string> one_of(const std::vector<std::string>& values) {
  return rc::gen::resize(rc::kNominalSize, rc::gen::elementOf(values));
}
bool coin() {
  return uniform(0, 2) == 1;
}

// Appends "--flag value" with probability 1/2.
void maybe(std::vector<std::string>& args, const std::string& flag,
           const std::vector<std::string>& values) {
  if (coin()) {
    args.push_back(flag);
    args.push_back(*one_of(values));
  }
}
void maybe_flag(std::vector<std::string>& args, const std::string& flag) {
  if (coin()) args.push_back(flag);
}

std::vector<std::string> metric_args(std::vector<std::string> args) {
  maybe(args, "--filter", kFilters);
  maybe(args, "--acuity", kAcuity);
  maybe(args, "--norm", kNorms);
  return args;
}

// A random command line of one of the commands, small enough to run fast.
std::vector<std::string> random_command() {
  const int which = uniform(0, 23);
  std::vector<std::string> a;
  switch (which) {
    case 0:
      a = metric_args({"eval", *one_of(kPatterns)});
      if (coin()) a.push_back(*one_of(kPatterns));
      maybe_flag(a, "--json");
      maybe(a, "--profile", {"profile.svg", "profile.csv", "profile.txt", "folder"});
      break;
    case 1:
      a = {"show", *one_of(kPatterns)};
      maybe(a, "-o", {"out.svg", "out.json", "out.png", "folder", "-"});
      maybe_flag(a, "--json");
      break;
    case 2:
      a = metric_args(
          {"optimize", "--family", *one_of(kFamilies), "--starts", "2", "--iterations", "20"});
      maybe(a, "--placement",
            {"left,right,bottom,top", "inside", "corner", "top-left,bottom,right"});
      maybe(a, "--seed", kSeeds);
      maybe(a, "-o", {"best.json", "best.svg", "folder"});
      maybe(a, "--csv", {"starts.csv"});
      maybe(a, "--method", {"descent", "minimax", "anneal", "newton"});
      maybe(a, "--api", {"d3d12-tier1", "vulkan", "nosuch"});
      maybe_flag(a, "--json");
      break;
    case 3:
      a = metric_args({"optimize", *one_of(kPatterns), "--iterations", "20"});
      maybe(a, "--lock", {"0", "0,1", "99", "-1"});
      maybe_flag(a, "--nonnegative");
      break;
    case 4:
      a = {"enumerate", "--cost", *one_of({"1.25", "1.5", "1.3", "0", "nan", "1.25,2"})};
      // Optimizing every configuration (app_test covers it) takes minutes under
      // ASan: the property asks --optimize only of costs refused before it runs.
      if (a.back() == "0" || a.back() == "nan") maybe_flag(a, "--optimize");
      maybe(a, "--csv", {"enum.csv"});
      maybe(a, "--best-dir", {"best", "good.json"});
      maybe_flag(a, "--json");
      break;
    case 5:
      a = {"generate", *one_of(kGenerators), "--n", *one_of(kCounts)};
      maybe(a, "--seed", kSeeds);
      maybe(a, "-o", {"pts.csv", "pts.json", "pts.txt", "folder"});
      maybe(a, "--tile", {"2", "0", "99"});
      maybe_flag(a, "--json");
      break;
    case 6:
      a = {"discrepancy", *one_of(kGenerators), "--n", *one_of(kCounts)};
      maybe_flag(a, "--json");
      break;
    case 7:
      a = {"spectrum", *one_of(kGenerators),
           "--n",      *one_of(kCounts),
           "--size",   *one_of({"8", "16", "7", "100000"})};
      maybe(a, "-o", {"spec.png", "spec.svg"});
      maybe(a, "--csv", {"spec.csv"});
      maybe(a, "--1d", {"poisson", "jittered", "nosuch"});
      maybe_flag(a, "--json");
      break;
    case 8:
      a = {"render",        *one_of(kScenes),      "--size",
           *one_of(kSizes), "--reference-samples", *one_of({"4", "16", "2", "0"})};
      if (coin()) {
        a.insert(a.end(), {"--pattern", *one_of(kPatterns)});
      } else {
        a.insert(a.end(), {"--generator", *one_of(kGenerators), "--samples", *one_of(kCounts)});
        maybe(a, "--filter", kFilters);
      }
      maybe(a, "-o", {"img.png", "img.jpg"});
      maybe(a, "--error", {"err.png"});
      maybe(a, "--histogram", {"hist.csv"});
      maybe_flag(a, "--grid");
      maybe_flag(a, "--json");
      maybe(a, "--rotate", {"30", "nan", "1e308"});
      maybe(a, "--cache", {"good.json"});  // a file: warned about, then no cache
      break;
    case 9:
      a = {"animate",
           *one_of({"circle", "triangle", "nosuch"}),
           "--pattern",
           *one_of(kPatterns),
           "--size",
           *one_of({"8", "12", "0"}),
           "--frames",
           *one_of({"1", "2", "0"}),
           "--reference-samples",
           "4"};
      maybe(a, "--gif", {"anim.gif", "anim.png"});
      maybe(a, "--frames-dir", {"frames", "good.json"});
      maybe(a, "--filter", kFilters);
      maybe_flag(a, "--json");
      break;
    case 10:
      a = metric_args({"snap", *one_of(kPatterns)});
      maybe_flag(a, "--optimize-weights");
      maybe_flag(a, "--nonnegative");
      maybe(a, "-o", {"snapped.json", "snapped.txt"});
      maybe(a, "--lattice", {"16", "1", "1000000"});
      maybe_flag(a, "--json");
      break;
    case 11:
      a = {"export", *one_of(kPatterns), "--api",
           *one_of({"d3d12-tier1", "d3d12-tier2", "vulkan", "metal", "gl", "nosuch"})};
      maybe(a, "-o", {"layout.h"});
      maybe(a, "--grid", {"2x2", "0x0", "abc"});
      break;
    case 12:
      a = {"import", *one_of({"good.json", "bad.json", "folder", "missing.h", "points.csv"})};
      break;
    case 13:
      a = {"list"};
      maybe_flag(a, "--json");
      break;
    case 14:
      a = metric_args({"table3", "--patterns", *one_of({"2", "0"}), "--iterations", "5"});
      maybe_flag(a, "--json");
      break;
    case 15:
      a = {"table2", "--size", *one_of({"8", "0"}), "--frames", "1", "--reference-samples", "4"};
      maybe_flag(a, "--json");
      break;
    case 16:  // engine TAA: presets, ratios, motions, overrides, sequences
      a = {"animate",
           *one_of({"checkerboard", "zoneplate", "circle", "good.json", "nosuch"}),
           "--taa",
           *one_of({"ue4", "fsr2", "godot", "bevy", "bevy-0.16", "nosuch"}),
           "--size",
           *one_of({"8", "12"}),
           "--frames",
           *one_of({"1", "3", "0"}),
           "--warmup",
           *one_of({"2", "-3", "100000"}),
           "--reference-samples",
           "4"};
      maybe(a, "--ratio", {"1", "1.5", "3", "0.5", "nan", "inf", "9"});
      maybe(a, "--motion",
            {"pan:dx=0.5,dy=0.25", "rotate:deg=2", "static", "pan:dx=100", "pan:foo=1",
             "rotate:deg=nan", "orbit"});
      maybe(a, "--taa-set",
            {"history=catmull-rom-5", "gamma=1.5", "alpha=0.1", "gamma=-1", "bogus=1", "history",
             "reconstruct=gaussian:sigma=0.5,radius=1.5", "rectify=sideways", "jitter_sign=-1",
             "jitter_sign=0", "resolve=generic", "resolve=fsr2-2.2", "resolve=ue4-4.26",
             "resolve=fsr3", "reset_count=7", "reset_count=0"});
      maybe(a, "--sequence", {"halton:frames=2", "r2", "aapat-taa-8", "msaa-alternating"});
      maybe(a, "--frames-dir", {"frames", "good.json"});
      maybe(a, "--csv", {"rows.csv"});
      maybe_flag(a, "--cut");
      maybe_flag(a, "--json");
      break;
    case 17:  // jitters under a preset's history while panning (one velocity, few frames:
              // an evaluation's kernels are large)
      a = {"sequence",
           "pan",
           *one_of({"halton:frames=2", "r2:frames=3", "msaa-alternating:samples=2,frames=2",
                    "random:frames=3,seed=4", "display-lattice:ratio=2,frames=4",
                    "display-lattice:ratio=0.5,frames=4", "nosuch"}),
           "--taa",
           *one_of({"ue4", "fsr2", "godot", "bevy", "nosuch"}),
           "--acuity",
           *one_of({"uniform:step=30", "uniform:step=0"}),
           "--velocity",
           *one_of({"0,0", "0.37,0.21", "1e9,0", "nan,1", "1", "a,b"})};
      maybe(a, "--ratio", {"1", "1.5", "0.5", "nan"});
      maybe(a, "--random-velocities", {"1", "2", "0", "257", "-1"});
      maybe(a, "--max-speed", {"0.5", "0", "nan", "17"});
      maybe(a, "--seed", {"3", "x"});
      maybe(a, "--taa-set",
            {"history=catmull-rom-5", "alpha=0.2", "alpha=0", "bogus=1", "history"});
      maybe_flag(a, "--json");
      break;
    case 18:  // the sequence search, tiny
      a = {"optimize", "--sequence", *one_of({"2", "3", "0"}),
           "--starts", "1",          "--iterations",
           "30",       "-o",         *one_of({"seq.json", "seq.txt"})};
      maybe(a, "--jitter-bound", {"0.3", "0.05", "0.5", "0", "0.7", "nan"});
      maybe(a, "--jitter-radius", {"0.3", "0.05", "0.71", "0", "1", "inf"});
      maybe(a, "--flicker-weight", {"1", "-1"});
      maybe(a, "--api", {"vulkan", "nosuch"});
      maybe(a, "--ratio", {"1.5", "0.5"});
      maybe_flag(a, "--json");
      break;
    case 19:  // the search under motion, tiny (one velocity, one step size)
      a = {"optimize",
           "--sequence",
           *one_of({"2", "3", "0", "200"}),
           "--taa",
           *one_of({"fsr2", "godot", "nosuch"}),
           "--acuity",
           "uniform:step=30",
           "--velocity",
           *one_of({"0,0", "0.37,0.21", "nan,1", "a,b"}),
           "--step",
           *one_of({"0.25", "0", "nan"}),
           "--min-step",
           *one_of({"0.25", "0.5"}),
           "-o",
           *one_of({"seq.json", "seq.txt"})};
      maybe(a, "--from", {"r2:frames=2", "halton:frames=3", "nosuch"});
      maybe(a, "--taa-set", {"history=catmull-rom-5", "bogus=1"});
      maybe(a, "--jitter-bound", {"0.3", "0"});
      maybe_flag(a, "--json");
      break;
    case 20:  // the rendered comparison, tiny (few small scenes, few frames)
      a = {"sequence", "compare", *one_of({"halton:frames=2", "r2:frames=3", "nosuch"}),
           // bevy-halton's centre frame: FSR 2 never takes it (a warning)
           *one_of({"halton:frames=4", "random:frames=3,seed=2", "aapat-taa-8",
                    "bevy-halton:frames=4"}),
           "--taa", *one_of({"bevy", "godot", "fsr2", "nosuch"}), "--size",
           *one_of({"12", "10x8", "0", "5000"}), "--frames", *one_of({"2", "0"}), "--warmup",
           *one_of({"1", "-1"}), "--reference-samples", "4"};
      if (uniform(0, 2) == 0)
        a.insert(a.end(), {"--random-scenes", *one_of({"2", "0", "2000"})});
      else
        a.insert(a.end(), {"--scene", *one_of({"random-shapes:count=3", "disc", "nosuch"})});
      maybe(a, "--motion", {"static", "cut", "random-pan", "pan:dx=0.3,dy=0.1", "spin"});
      maybe(a, "--shapes", {"3", "0"});
      maybe(a, "--max-speed", {"0.5", "nan"});
      maybe(a, "--resamples", {"50", "0"});
      maybe_flag(a, "--json");
      break;
    case 21:  // the rendered search, tiny (one small scene, a few tries)
      a = {"sequence",
           "search",
           *one_of({"halton:frames=2", "r2:frames=3", "msaa-alternating", "nosuch"}),
           "--taa",
           *one_of({"bevy", "godot", "nosuch"}),
           "--random-scenes",
           *one_of({"1", "0"}),
           "--size",
           *one_of({"10", "0"}),
           "--frames",
           "2",
           "--warmup",
           "1",
           "--reference-samples",
           "4",
           "--max-tries",
           *one_of({"3", "-1"})};
      maybe(a, "--against", {"halton:frames=4", "nosuch"});
      maybe(a, "--motion", {"random-pan", "cut", "spin"});
      maybe(a, "--loss", {"0", "-1", "nan"});
      maybe(a, "--step", {"0.125", "0", "0.75"});
      maybe(a, "-o", {"s.json", "s.txt"});
      maybe_flag(a, "--unbiased");
      maybe_flag(a, "--json");
      break;
    case 22:  // the perceptual objective, tiny charts: eval and refine
      a = {coin() ? "eval" : "refine", *one_of(kPatterns), "--objective",
           *one_of({"perceptual:angles=1,patch=16,reference=16",
                    "perceptual:angles=1,patch=16,reference=16,box=1", "perceptual:ppd=0.5",
                    "perceptual:ppd=1001", "perceptual:edge=0,line=0,thin=0,dot=0",
                    "perceptual:background=nan", "perceptual:foreground=0,background=0",
                    "perceptual:reference=20", "perceptual:nosuch=1", "perceptual:angles=0"})};
      if (a[0] == "refine") {
        a.insert(a.end(), {"--max-tries", *one_of({"3", "0", "-2"})});
        maybe(a, "-o", {"refined.json", "refined.png", "folder"});
        maybe(a, "--api", {"vulkan", "metal", "nosuch"});
        maybe(a, "--weight-steps", {"2", "-1", "10001"});
        if (coin()) {  // on scenes instead of the charts (the spec then clashes)
          a.insert(a.end(), {"--scenes", *one_of({"spiral", "nosuch", "disc"}), "--size",
                             *one_of({"8", "4", "9x8"}), "--reference-samples", "4"});
          maybe(a, "--measure", {"rmse", "flip", "psnr"});
        }
      }
      maybe_flag(a, "--json");
      break;
  }
  return a;
}

std::string joined(const std::vector<std::string>& args) {
  std::string s = "aapat";
  for (const auto& a : args) s += " '" + a + "'";
  return s;
}

RC_GTEST_PROP(CommandProperty, EveryCommandExitsCleanlyAndLeavesNothingOnError, ()) {
  const fs::path dir = workspace();
  const std::vector<std::string> args = random_command();
  const std::set<std::string> before = listing(dir);
  const Outcome o = run_process(args, dir, 120);
  RC_LOG() << joined(args) << "\n" << o.err;
  RC_TAG(args[0], o.code);  // the mix of commands and outcomes, printed at the end
  RC_ASSERT(!o.timed_out);
  RC_ASSERT(o.signal == 0);
  RC_ASSERT(o.exited);
  RC_ASSERT(o.code == kExitOk || o.code == kExitError || o.code == kExitUsage);
  const std::set<std::string> after = listing(dir);
  if (o.code != kExitOk) {
    RC_ASSERT(!o.err.empty());
    RC_ASSERT(o.err.find("internal error") == std::string::npos);
    RC_ASSERT(after == before);  // nothing written, nothing half-written
  } else {
    // What a successful run wrote is removed, so that the next case starts alike.
    for (const std::string& f : after)
      if (!before.contains(f)) fs::remove_all(dir / f);
  }
}

}  // namespace
}  // namespace aapat
