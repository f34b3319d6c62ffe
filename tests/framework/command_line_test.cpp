// The lab command line is one table: the usage text lists every option the parser accepts, and the
// parser's errors name the option and what it wants.
#include "common/shell/command_line.hpp"
#include "common/base/error.hpp"

#include <gtest/gtest.h>

#include <regex>

TEST(CommandLineTable, UsageListsEveryAcceptedOption) {
  std::string accepted;
  try {
    const char* argv[] = {"lab", "--no-such-option"};
    wb::parseCommandLine(2, argv);
  } catch (const wb::UsageError& e) {
    accepted = e.what();
  }
  ASSERT_NE(accepted.find("accepted:"), std::string::npos) << accepted;
  const std::string usage = wb::usageText("lab", "scenes/x.json");
  const std::regex option("--[a-z-]+");
  int count = 0;
  for (std::sregex_iterator it(accepted.begin() + long(accepted.find("accepted:")), accepted.end(), option), end;
       it != end; ++it, ++count)
    EXPECT_NE(usage.find("  " + it->str()), std::string::npos) << it->str() << " is accepted but not in the usage";
  EXPECT_GE(count, 15);
  EXPECT_NE(usage.find("scenes/x.json"), std::string::npos);
}

TEST(CommandLineTable, ValuesAreParsedAndCheckedByTheTable) {
  const char* argv[] = {"lab",      "--headless", "--size",    "64x48",  "--set",   "a=1",
                        "--set",    "b=2",        "--compare", "k=x,y",  "--sweep", "s=1,2,3",
                        "--frames", "5",          "--record",  "r.json", "--quiet"};
  const wb::Options o = wb::parseCommandLine(int(std::size(argv)), argv);
  EXPECT_TRUE(o.headless && o.quiet);
  EXPECT_EQ(o.size, glm::ivec2(64, 48));
  EXPECT_EQ(o.sets, (std::vector<std::string>{"a=1", "b=2"}));
  EXPECT_TRUE(o.compare.on);
  EXPECT_EQ(o.compare.b, "y");
  ASSERT_EQ(o.sweeps.size(), 1u);
  EXPECT_EQ(o.sweeps[0].second.size(), 3u);
  EXPECT_EQ(o.frames, 5);
  EXPECT_EQ(o.record, "r.json");
  const char* missing[] = {"lab", "--scene"};
  EXPECT_THROW(wb::parseCommandLine(2, missing), wb::UsageError);
}

// What the command line sets, a scene may not override (lab 07's light.size starts at the scene's).
TEST(CommandLineTable, NamesTheSettingsItSets) {
  const char* argv[] = {"lab", "--set", "a=1", "--compare", "k=x,y", "--sweep", "s=1,2", "--set", "ab=3"};
  const wb::Options o = wb::parseCommandLine(int(std::size(argv)), argv);
  for (const char* key : {"a", "k", "s", "ab"}) EXPECT_TRUE(o.names(key)) << key;
  for (const char* key : {"b", "x", "light.size", "a=1"}) EXPECT_FALSE(o.names(key)) << key;
}
