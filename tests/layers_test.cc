// The rooms' layering (cmake/check_layers.cmake, run by every build before camopt_core compiles):
// the real tree passes, and a tree with a model/ header that includes an objectives/ or an
// optimizers/ header, a cad/ file that includes a studies/ header, an objectives/ or optimizers/
// file that includes a sizing driver, or a sizing driver that includes studies/, fails with the file
// named; a sizing driver may include optimizers/ and objectives/.
#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "tests/test_util.h"

namespace camopt {
namespace layers_test {

namespace fs = std::filesystem;
using camopt::testing::ReadFile;
using camopt::testing::TempDir;
using camopt::testing::WriteFile;

struct Checked {
  int exit_code;
  std::string output;
};

Checked CheckLayers(const fs::path& source_dir, const fs::path& log) {
  const std::string command = std::string(CAMOPT_CMAKE_COMMAND) + " -DSOURCE_DIR=" + source_dir.string() + " -P " +
                              (fs::path(CAMOPT_SOURCE_DIR) / "cmake" / "check_layers.cmake").string() + " > " +
                              log.string() + " 2>&1";
  const int status = std::system(command.c_str());
  return {WEXITSTATUS(status), ReadFile(log)};
}

TEST(Layers, TheTreeIsLayered) {
  const auto dir = TempDir("layers-tree");
  const Checked c = CheckLayers(CAMOPT_SOURCE_DIR, dir / "log");
  EXPECT_EQ(c.exit_code, 0) << c.output;
}

TEST(Layers, AModelHeaderIncludingObjectivesOrOptimizersFailsTheBuild) {
  for (const char* wrong : {"objectives/problem.h", "optimizers/solver.h", "studies/study.h"}) {
    SCOPED_TRACE(wrong);
    const auto dir = TempDir("layers-planted");
    fs::create_directories(dir / "model" / "lcr");
    WriteFile(dir / "model" / "lcr" / "fine.h", "#pragma once\n#include <cmath>\n#include \"model/common/scalar.h\"\n");
    WriteFile(dir / "model" / "lcr" / "wrong.h", std::string("#pragma once\n#include \"") + wrong + "\"\n");
    const Checked c = CheckLayers(dir, dir / "log");
    EXPECT_NE(c.exit_code, 0) << c.output;
    EXPECT_NE(c.output.find(std::string("model/lcr/wrong.h includes ") + wrong), std::string::npos) << c.output;
    EXPECT_EQ(c.output.find("fine.h"), std::string::npos) << c.output;
  }
  // cad/ may use model/ but not studies/; objectives/ not optimizers/.
  const auto dir = TempDir("layers-planted-2");
  fs::create_directories(dir / "cad");
  fs::create_directories(dir / "objectives");
  WriteFile(dir / "cad" / "x.cc", "#include \"model/common/scalar.h\"\n#include \"studies/writers.h\"\n");
  WriteFile(dir / "objectives" / "y.h", "#include \"optimizers/solver.h\"\n");
  const Checked c = CheckLayers(dir, dir / "log");
  EXPECT_NE(c.exit_code, 0);
  EXPECT_NE(c.output.find("cad/x.cc includes studies/writers.h"), std::string::npos) << c.output;
  EXPECT_EQ(c.output.find("cad/x.cc includes model/"), std::string::npos) << c.output;
  EXPECT_NE(c.output.find("objectives/y.h includes optimizers/solver.h"), std::string::npos) << c.output;
}

TEST(Layers, SizingDriversSitAboveObjectivesAndOptimizers) {
  const auto dir = TempDir("layers-sizing");
  for (const char* room : {"sizing", "objectives", "optimizers"}) fs::create_directories(dir / room);
  WriteFile(dir / "sizing" / "fine.h",
            "#include \"optimizers/solver.h\"\n#include \"objectives/problem.h\"\n#include \"model/common/scalar.h\"\n");
  WriteFile(dir / "sizing" / "up.cc", "#include \"studies/study.h\"\n");
  WriteFile(dir / "objectives" / "down.cc", "#include \"sizing/lcr_min_size.h\"\n");
  WriteFile(dir / "optimizers" / "down.cc", "#include \"sizing/cycloid_min_size.h\"\n");
  const Checked c = CheckLayers(dir, dir / "log");
  EXPECT_NE(c.exit_code, 0);
  EXPECT_EQ(c.output.find("fine.h"), std::string::npos) << c.output;
  EXPECT_NE(c.output.find("sizing/up.cc includes studies/study.h"), std::string::npos) << c.output;
  EXPECT_NE(c.output.find("objectives/down.cc includes sizing/lcr_min_size.h"), std::string::npos) << c.output;
  EXPECT_NE(c.output.find("optimizers/down.cc includes sizing/cycloid_min_size.h"), std::string::npos) << c.output;
}

}  // namespace layers_test
}  // namespace camopt
