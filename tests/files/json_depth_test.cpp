// One nesting limit for every JSON the product reads: the last level it allows parses, one more
// is refused at its own position, and glTF (not our format) is spared the duplicate-key rule.
#include <gtest/gtest.h>

#include "util/json_text.h"

namespace penumbra {
namespace {

std::string nested(int depth) { return std::string(static_cast<size_t>(depth), '[') + std::string(static_cast<size_t>(depth), ']'); }

TEST(JsonDepth, TheLimitIsExactAndReportedWhereItIsPassed) {
  EXPECT_FALSE(scan_json_text(nested(kMaxJsonDepth)));
  std::optional<JsonTextProblem> p = scan_json_text(nested(kMaxJsonDepth + 1));
  ASSERT_TRUE(p);
  EXPECT_EQ(p->line, 1);
  EXPECT_EQ(p->column, kMaxJsonDepth + 1);
  EXPECT_EQ(p->message, "nesting deeper than " + std::to_string(kMaxJsonDepth) + " levels");
}

TEST(JsonDepth, DuplicateKeysAreOursToRefuseOnly) {
  const std::string text = R"({"a": 1, "a": 2})";
  ASSERT_TRUE(scan_json_text(text));
  EXPECT_FALSE(scan_json_text(text, /*duplicate_keys=*/false));
  EXPECT_TRUE(scan_json_text(nested(kMaxJsonDepth + 1), /*duplicate_keys=*/false));
}

}  // namespace
}  // namespace penumbra
