#include "dream/workflows/seed_list.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace dream::workflows {
namespace {

std::string ErrorOf(const std::string& text) {
  try {
    ParseSeedList(text);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(SeedList, SingleRangeAndListKeepTheGivenOrder) {
  EXPECT_EQ(ParseSeedList("7"), (std::vector<uint64_t>{7}));
  EXPECT_EQ(ParseSeedList("1-4"), (std::vector<uint64_t>{1, 2, 3, 4}));
  EXPECT_EQ(ParseSeedList("9,0,3-5"), (std::vector<uint64_t>{9, 0, 3, 4, 5}));
  EXPECT_EQ(ParseSeedList("5-5"), (std::vector<uint64_t>{5}));
  EXPECT_EQ(ParseSeedList("9223372036854775807"), (std::vector<uint64_t>{kMaxSeed}));
}

TEST(SeedList, BadTextNamesThePart) {
  EXPECT_NE(ErrorOf("20-1").find("range 20-1 runs backwards; write 1-20"), std::string::npos) << ErrorOf("20-1");
  EXPECT_NE(ErrorOf("1-x").find("'1-x' is not a seed"), std::string::npos) << ErrorOf("1-x");
  EXPECT_NE(ErrorOf("-3").find("'-3' is not a seed"), std::string::npos) << ErrorOf("-3");
  EXPECT_NE(ErrorOf("1.5").find("'1.5' is not a seed"), std::string::npos);
  EXPECT_NE(ErrorOf("1-2-3").find("'1-2-3' is not a seed"), std::string::npos) << ErrorOf("1-2-3");
  EXPECT_NE(ErrorOf("1,,2").find("empty item"), std::string::npos);
  EXPECT_NE(ErrorOf("1,").find("empty item"), std::string::npos);
  EXPECT_NE(ErrorOf("").find("no seeds"), std::string::npos);
  EXPECT_NE(ErrorOf("1-5,3").find("seed 3 is given twice"), std::string::npos) << ErrorOf("1-5,3");
  EXPECT_NE(ErrorOf("9223372036854775808").find("too large"), std::string::npos);
  EXPECT_NE(ErrorOf("99999999999999999999999").find("too large"), std::string::npos);
  EXPECT_NE(ErrorOf("0-100000").find("more than 100000 seeds"), std::string::npos) << ErrorOf("0-100000");
  EXPECT_NE(ErrorOf("0-99999,100000").find("more than 100000 seeds"), std::string::npos);
}

}  // namespace
}  // namespace dream::workflows
