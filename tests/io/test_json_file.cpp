/// @file
/// JSON inputs: every failure an InputError naming the source, no stack overflow, short
/// messages.

#include <gtest/gtest.h>

#include <string>

#include "io_test_support.hpp"
#include "tailor/io/json_file.hpp"

namespace tailor {
namespace {

using test::expect_contains;
using test::input_error_message;
using test::TempDir;

std::string nested_arrays(int depth) {
  return std::string(static_cast<std::size_t>(depth), '[') +
         std::string(static_cast<std::size_t>(depth), ']');
}

TEST(JsonFile, ParsesOrdinaryJson) {
  const nlohmann::json j = parse_json_text(R"({"a": [1, 2.5, "x"], "b": {"c": null}})", "t.json");
  EXPECT_EQ(j["a"][1], 2.5);
  EXPECT_TRUE(j["b"]["c"].is_null());
  EXPECT_NO_THROW(parse_json_text(nested_arrays(kMaxJsonDepth), "deep-but-fine.json"));
}

TEST(JsonFile, DeepNestingIsRefusedWithoutRecursion) {
  // The issue's case: 100,000 levels used to overflow the stack when dumped.
  const std::string text = R"({"arm": )" + nested_arrays(100'000) + "}";
  expect_contains(input_error_message([&] { parse_json_text(text, "deep.json"); }),
                  {"deep.json", "nested deeper than 64 levels"});
}

TEST(JsonFile, NumberOutOfRangeIsAnInputError) {
  // nlohmann::json throws out_of_range (not parse_error) for 1e400.
  expect_contains(
      input_error_message([] { parse_json_text(R"({"gravity": [0, 1e400, 0]})", "big.json"); }),
      {"big.json", "1e400"});
}

TEST(JsonFile, MalformedJsonQuotesAShortExcerpt) {
  const std::string text = "[\"" + std::string(1'000'000, 'z') + "\\q\"]";  // a bad escape
  const std::string message = input_error_message([&] { parse_json_text(text, "bad.json"); });
  expect_contains(message, {"bad.json", "malformed JSON"});
  EXPECT_LT(message.size(), 300u) << message.substr(0, 400);
}

TEST(JsonFile, ReadsFilesAndNamesThem) {
  TempDir dir;
  test::write_bytes(dir / "ok.json", "[true]");
  EXPECT_EQ(read_json_file(dir / "ok.json"), nlohmann::json::parse("[true]"));
  expect_contains(input_error_message([&] { read_json_file(dir / "absent.json"); }),
                  {"absent.json", "cannot open"});
  test::write_bytes(dir / "empty.json", "");
  expect_contains(input_error_message([&] { read_json_file(dir / "empty.json"); }),
                  {"empty.json", "malformed JSON"});
}

TEST(JsonFile, LargeTextIsRefusedBeforeParsing) {
  const test::ScopedMemoryBudget budget(1 << 20);
  const std::string text = "[" + std::string(100'000, ' ') + "]";  // 100 KB: 3.2 MB budgeted
  expect_contains(input_error_message([&] { parse_json_text(text, "large.json"); }),
                  {"large.json", "memory budget"});
}

TEST(JsonFile, ExcerptIsShortWhateverTheValue) {
  const nlohmann::json deep = parse_json_text(nested_arrays(kMaxJsonDepth), "d");
  EXPECT_LE(json_excerpt(deep).size(), 40u) << json_excerpt(deep);
  nlohmann::json wide = nlohmann::json::array();
  for (int i = 0; i < 100'000; ++i) wide.push_back(i);
  EXPECT_EQ(json_excerpt(wide).substr(0, 10), "[0, 1, 2, ");
  EXPECT_LE(json_excerpt(wide).size(), 40u);
  EXPECT_EQ(json_excerpt(nlohmann::json("a\nb")), "\"a\\x0ab\"");
  EXPECT_EQ(json_excerpt(nlohmann::json(2.5)), "2.5");
}

TEST(JsonFile, WithJsonErrorsNamesTheSource) {
  const nlohmann::json j = nlohmann::json::parse(R"({"a": "text"})");
  expect_contains(input_error_message(
                      [&] { with_json_errors("s.json", [&] { return j.at("a").get<int>(); }); }),
                  {"s.json", "type must be number"});
  EXPECT_EQ(with_json_errors("s.json", [&] { return j.at("a").get<std::string>(); }), "text");
}

}  // namespace
}  // namespace tailor
