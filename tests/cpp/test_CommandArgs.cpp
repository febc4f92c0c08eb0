#include <gtest/gtest.h>

#include "core/CommandArgs.h"
#include "core/OpenSeesError.h"

using beamsolid::CommandArgs;
using beamsolid::OpenSeesError;

TEST(CommandArgs, ReadsTypedValuesInOrder) {
  CommandArgs a("node", {1LL, 2.5, std::string("-ndf"), 3LL});
  EXPECT_EQ(a.nextInt("tag"), 1);
  EXPECT_DOUBLE_EQ(a.nextDouble("x"), 2.5);
  EXPECT_TRUE(a.nextFlag("-ndf"));
  EXPECT_EQ(a.nextInt("ndf"), 3);
  EXPECT_TRUE(a.done());
}

TEST(CommandArgs, WrongTypeNamesArgumentAndValue) {
  CommandArgs a("node", {std::string("abc")});
  a.setContext("node");
  try {
    a.nextInt("tag");
    FAIL() << "expected OpenSeesError";
  } catch (const OpenSeesError& e) {
    EXPECT_STREQ(e.what(), "node: argument 1 (tag): expected an integer, got 'abc'");
  }
}

TEST(CommandArgs, MissingArgumentSaysHowManyThereAre) {
  CommandArgs a("fix", {1LL});
  a.nextInt("nodeTag");
  EXPECT_THROW(a.nextInt("flag"), OpenSeesError);
}

TEST(CommandArgs, IntegralFloatIsAcceptedAsInteger) {
  CommandArgs a("node", {3.0, 3.5});
  EXPECT_EQ(a.nextInt("tag"), 3);
  EXPECT_THROW(a.nextInt("tag"), OpenSeesError);
}
