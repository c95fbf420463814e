// Study definitions: ranges parse to the values they say, combinations are
// numbered like nested loops (first key outermost), shards partition the
// combinations, and malformed input is refused with what is wrong.
#include <gtest/gtest.h>

#include <railstab/study/study_definition.hpp>

#include <set>

using namespace railstab;

TEST(StudyDefinition, RangesGiveTheirValuesAndEndExactlyAtTo) {
  const VariedKey v = parse_varied_key("contacts.c.conicity=0.1:0.3:0.1");
  EXPECT_EQ(v.key, "contacts.c.conicity");
  ASSERT_EQ(v.values.size(), 3u);
  EXPECT_EQ(v.values[0], 0.1);
  EXPECT_EQ(v.values[1], 0.1 + 0.1);
  EXPECT_EQ(v.values[2], 0.3);  // not 0.1 + 2 * 0.1 = 0.30000000000000004
  EXPECT_EQ(parse_varied_key("k=0.05:0.14:0.01").values[1], 0.06);  // not 0.060000000000000005
  EXPECT_EQ(parse_varied_key("k=5:5:1").values, std::vector<double>{5.0});
  EXPECT_EQ(parse_varied_key("a.b[1]=1e5:5e5:1e5").values.size(), 5u);
  EXPECT_EQ(varied_key_text(v), "contacts.c.conicity=0.1:0.3:0.1");
  for (const char* bad : {"k", "=1:2:1", "k=1:2", "k=1:2:3:4", "k=2:1:1", "k=1:2:0", "k=1:2:-1",
                          "k=1:2:0.3", "k=a:2:1", "k=1:nan:1", "k=0:1e9:1e-9"})
    EXPECT_THROW(parse_varied_key(bad), std::invalid_argument) << bad;
}

TEST(StudyDefinition, LinkedKeysShareOneRange) {
  const VariedKey v = parse_varied_key("e.front.c,e.rear.c=1:3:1");
  EXPECT_EQ(v.key, "e.front.c,e.rear.c");
  EXPECT_EQ(v.keys, (std::vector<std::string>{"e.front.c", "e.rear.c"}));
  EXPECT_EQ(v.values, (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(varied_key_text(v), "e.front.c,e.rear.c=1:3:1");
  EXPECT_EQ(parse_varied_key("k=1:2:1").keys, std::vector<std::string>{"k"});
  for (const char* bad : {"a,=1:2:1", ",a=1:2:1", "a,,b=1:2:1", "a,a=1:2:1"})
    EXPECT_THROW(parse_varied_key(bad), std::invalid_argument) << bad;
  StudyDefinition d;
  d.varied = {parse_varied_key("a,b=1:3:1"), parse_varied_key("b=10:20:10")};
  EXPECT_THROW(check_study_definition(d), std::invalid_argument);  // b varied twice
  d.varied.pop_back();
  EXPECT_NO_THROW(check_study_definition(d));
  d.fixed = {{"b", 1.0}};
  EXPECT_THROW(check_study_definition(d), std::invalid_argument);  // b linked and set
}

TEST(StudyDefinition, CombinationsAreNestedLoopsFirstKeyOutermost) {
  StudyDefinition d;
  d.varied = {parse_varied_key("a=1:3:1"), parse_varied_key("b=10:20:10")};
  ASSERT_EQ(d.combinations(), 6u);
  EXPECT_EQ(d.values_of(0), (std::vector<double>{1, 10}));
  EXPECT_EQ(d.values_of(1), (std::vector<double>{1, 20}));
  EXPECT_EQ(d.values_of(2), (std::vector<double>{2, 10}));
  EXPECT_EQ(d.values_of(5), (std::vector<double>{3, 20}));
  d.fixed = {{"a", 1.0}};
  EXPECT_THROW(check_study_definition(d), std::invalid_argument);  // varied and set
  d.fixed.clear();
  d.varied.push_back(parse_varied_key("a=1:2:1"));
  EXPECT_THROW(check_study_definition(d), std::invalid_argument);  // varied twice
  d.varied = {parse_varied_key("a=0:9999:1"), parse_varied_key("b=0:9999:1")};
  EXPECT_THROW(check_study_definition(d), std::invalid_argument);  // 1e8 combinations
  EXPECT_THROW(check_study_definition(StudyDefinition{}), std::invalid_argument);  // nothing varied
}

TEST(StudyDefinition, ShardsPartitionTheCombinations) {
  for (std::size_t n : {1u, 2u, 3u, 7u}) {
    std::multiset<std::size_t> seen;
    for (std::size_t i = 1; i <= n; ++i) {
      const StudyShard s = parse_study_shard(std::to_string(i) + "/" + std::to_string(n));
      for (std::size_t c = 0; c < 20; ++c)
        if (s.holds(c)) seen.insert(c);
    }
    ASSERT_EQ(seen.size(), 20u) << n;
    for (std::size_t c = 0; c < 20; ++c) EXPECT_EQ(seen.count(c), 1u);
  }
  for (const char* bad : {"0/3", "4/3", "1", "a/2", "1/0", "/2", "1/", "-1/2"})
    EXPECT_THROW(parse_study_shard(bad), std::invalid_argument) << bad;
}

TEST(StudyDefinition, Fnv1aMatchesItsPublishedTestVectors) {
  // FNV-1a 64: "" -> cbf29ce484222325, "a" -> af63dc4c8601ec8c (Fowler, Noll, Vo).
  EXPECT_EQ(fnv1a64_hex(""), "cbf29ce484222325");
  EXPECT_EQ(fnv1a64_hex("a"), "af63dc4c8601ec8c");
}
