// MPI is a module the program loads only under a launcher (src/distributed/mpi_module.h): a plain
// render must map no MPI library (the dynamic loader's own report, LD_DEBUG=files, lists every
// library it maps, whether needed by the binary or dlopened); under mpirun the module and Open
// MPI are loaded (that the renders are right there is mpi_render_test.cpp's and
// mpi_sweep_test.cpp's); and when the module cannot be loaded under mpirun every rank says
// where it looked and exits non-zero.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../support/eyetrace_process.h"
#include "../support/mpirun.h"
#include "../support/temp_files.h"
#include "../support/unity_id.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

using test::read_text;
using test::TempDir;

const std::string kScene = EYETRACE_SOURCE_DIR "/scenes/cornell-box.pbrt";

std::vector<std::string> render_args(const std::string& output) {
  return {"render", kScene, "--resolution", "16x16", "--spp", "1", "--threads", "1", "-q", "-o", output};
}

// `env LD_DEBUG=files [more variables] eyetrace ARGS`, its stdout and stderr (the loader's report) to `log`.
int run_with_loader_report(const std::vector<std::string>& variables, const std::vector<std::string>& args,
                           const std::string& log) {
  std::vector<std::string> words = {"LD_DEBUG=files"};
  words.insert(words.end(), variables.begin(), variables.end());
  words.push_back(test::eyetrace_binary());
  words.insert(words.end(), args.begin(), args.end());
  const pid_t pid = test::spawn_logged("env", words, log);
  return pid > 0 ? test::wait_exit(pid) : -1;
}

bool loaded(const std::string& report, const std::string& library) {
  return report.find("file=" + library) != std::string::npos ||
         report.find("/" + library) != std::string::npos;  // dlopened by path
}

TEST(MpiModule, APlainRenderMapsNoMpiLibrary) {
  TempDir dir("eyetrace_mpi_module");
  ASSERT_EQ(run_with_loader_report({}, render_args(dir.file("out.exr")), dir.file("log")), 0)
      << read_text(dir.file("log"));
  const std::string report = read_text(dir.file("log"));
  ASSERT_TRUE(loaded(report, "libembree3")) << "the loader's report lists the libraries the binary needs";
  EXPECT_FALSE(loaded(report, "libeyetrace_mpi"));
  EXPECT_FALSE(loaded(report, "libmpi"));
  EXPECT_FALSE(loaded(report, "libopen-pal"));
}

#if EYETRACE_WITH_MPI

TEST(MpiModule, UnderMpirunTheModuleAndMpiAreLoaded) {
  TempDir dir("eyetrace_mpi_module");
  std::vector<std::string> words = {"--oversubscribe", "-n", "2", "env", "LD_DEBUG=files", test::eyetrace_binary()};
  const std::vector<std::string> args = render_args(dir.file("out.exr"));
  words.insert(words.end(), args.begin(), args.end());
  test::allow_mpirun_as_root();
  const pid_t pid = test::spawn_logged("mpirun", words, dir.file("log"));
  ASSERT_GT(pid, 0);
  ASSERT_EQ(test::wait_exit(pid), 0) << read_text(dir.file("log"));
  const std::string report = read_text(dir.file("log"));
  EXPECT_TRUE(loaded(report, "libeyetrace_mpi.so"));
  EXPECT_TRUE(loaded(report, "libmpi.so"));
}

TEST(MpiModule, AMissingModuleUnderMpirunIsAnErrorNamingWhereItLooked) {
  TempDir dir("eyetrace_mpi_module");
  const std::string nowhere = dir.file("no-such-dir");
  std::vector<std::string> words = {"--oversubscribe",      "-n", "2", "env", "EYETRACE_MPI_MODULE_DIR=" + nowhere,
                                    test::eyetrace_binary()};
  const std::vector<std::string> args = render_args(dir.file("out.exr"));
  words.insert(words.end(), args.begin(), args.end());
  test::allow_mpirun_as_root();
  const pid_t pid = test::spawn_logged("mpirun", words, dir.file("log"));
  ASSERT_GT(pid, 0);
  EXPECT_NE(test::wait_exit(pid), 0);
  const std::string log = read_text(dir.file("log"));
  EXPECT_NE(log.find("MPI module libeyetrace_mpi.so cannot be loaded"), std::string::npos) << log;
  EXPECT_NE(log.find(nowhere + "/libeyetrace_mpi.so: not found"), std::string::npos) << log;
  EXPECT_FALSE(std::filesystem::exists(dir.file("out.exr")));
}

TEST(MpiModule, AnUnloadableModuleIsAnErrorWithTheLoadersReason) {
  // A launcher's environment without mpirun: the module is looked for as under mpirun, and this
  // one is not a shared object.
  TempDir dir("eyetrace_mpi_module");
  { std::ofstream(dir.file("libeyetrace_mpi.so")) << "not a shared object\n"; }
  setenv("OMPI_COMM_WORLD_SIZE", "2", 1);
  setenv("EYETRACE_MPI_MODULE_DIR", dir.path().c_str(), 1);
  const int code = test::run_eyetrace_logged(render_args(dir.file("out.exr")), dir.file("log"));
  unsetenv("EYETRACE_MPI_MODULE_DIR");
  unsetenv("OMPI_COMM_WORLD_SIZE");
  EXPECT_EQ(code, 1);
  const std::string log = read_text(dir.file("log"));
  EXPECT_NE(log.find(dir.file("libeyetrace_mpi.so") + ": "), std::string::npos) << log;
  EXPECT_EQ(log.find(": not found"), std::string::npos) << log;
}

#endif

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
