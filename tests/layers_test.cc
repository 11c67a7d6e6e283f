// The rooms' layering (CMakeLists.txt, "The engine, one library per room"): each room's library
// compiles against an include root that holds only its own folder and the rooms below it, so a
// header of a room above does not exist for it. Compiled here with the include directories the
// build gives each room (build/rooms/ROOM.includes, cmake/camopt_layers.cmake): a planted include of
// a room above fails with that header not found, one of the room itself or below compiles.
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/test_util.h"

namespace camopt {
namespace layers_test {

namespace fs = std::filesystem;
using camopt::testing::ReadFile;
using camopt::testing::TempDir;
using camopt::testing::WriteFile;

struct Compiled {
  int exit_code;
  std::string output;
};

// Compiles `#include "HEADER"` alone (syntax only) with ROOM's include directories.
Compiled CompileInRoom(const std::string& room, const std::string& header) {
  const fs::path includes = fs::path(CAMOPT_ROOMS_DIR) / (room + ".includes");
  std::istringstream dirs(ReadFile(includes));
  std::string flags;
  int count = 0;
  for (std::string dir; std::getline(dirs, dir);) {
    if (dir.empty()) continue;
    flags += " -I'" + dir + "'";
    ++count;
  }
  EXPECT_GT(count, 0) << includes;
  const auto dir = TempDir("layers-" + room);
  WriteFile(dir / "planted.cc", "#include \"" + header + "\"\n");
  const std::string command = std::string(CAMOPT_CXX_COMPILER) + " -std=c++20 -fsyntax-only" + flags + " " +
                              (dir / "planted.cc").string() + " > " + (dir / "log").string() + " 2>&1";
  const int status = std::system(command.c_str());
  return {WEXITSTATUS(status), ReadFile(dir / "log")};
}

void ExpectRefused(const std::string& room, const std::string& header) {
  SCOPED_TRACE(room + " includes " + header);
  ASSERT_TRUE(fs::exists(fs::path(CAMOPT_SOURCE_DIR) / header)) << "the planted header must exist";
  const Compiled c = CompileInRoom(room, header);
  EXPECT_NE(c.exit_code, 0) << c.output;
  EXPECT_NE(c.output.find(header + ": No such file or directory"), std::string::npos) << c.output;
}

void ExpectCompiles(const std::string& room, const std::string& header) {
  SCOPED_TRACE(room + " includes " + header);
  const Compiled c = CompileInRoom(room, header);
  EXPECT_EQ(c.exit_code, 0) << c.output;
}

TEST(Layers, ModelSeesOnlyModel) {
  ExpectCompiles("model", "model/common/scalar.h");
  for (const char* above : {"cad/dxf.h", "objectives/problem.h", "optimizers/solver.h", "sizing/limit_slope.h",
                            "studies/study.h"})
    ExpectRefused("model", above);
}

TEST(Layers, CadSeesModelButNoRoomAbove) {
  ExpectCompiles("cad", "cad/dxf.h");
  ExpectCompiles("cad", "model/common/geometry.h");
  for (const char* above : {"objectives/problem.h", "studies/writers.h"}) ExpectRefused("cad", above);
}

TEST(Layers, ObjectivesSeeModelNotOptimizersSizingOrStudies) {
  ExpectCompiles("objectives", "objectives/problem.h");
  for (const char* above : {"optimizers/solver.h", "sizing/lcr_min_size.h", "studies/study.h", "cad/dxf.h"})
    ExpectRefused("objectives", above);
}

TEST(Layers, OptimizersSeeObjectivesNotSizingOrStudies) {
  ExpectCompiles("optimizers", "optimizers/solver.h");
  for (const char* above : {"sizing/cycloid_min_size.h", "studies/study.h"}) ExpectRefused("optimizers", above);
}

TEST(Layers, SizingSitsAboveOptimizersAndBelowStudies) {
  ExpectCompiles("sizing", "sizing/limit_slope.h");
  ExpectCompiles("sizing", "optimizers/solver.h");
  ExpectRefused("sizing", "studies/study.h");
}

}  // namespace layers_test
}  // namespace camopt
