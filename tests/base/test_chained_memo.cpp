// The memory that tries the entry that followed the last one first
// (base/chained_memo.h): whatever the order of asking, a key finds what
// was put under it, and nothing once it is forgotten.
#include <catch2/catch.hpp>

#include <cstdint>
#include <vector>

#include "base/chained_memo.h"

namespace {

using Key = std::vector<std::uint64_t>;

}  // namespace

TEST_CASE("a chained memory finds each key's value in the order it was put and in any other", "[memo][base]") {
  rs::base::ChainedMemo<int> memo(16);
  const std::vector<Key> keys = {{1, 2, 3}, {1, 2, 4}, {7}, {}, {1, 2, 3, 0}};
  for (std::size_t i = 0; i < keys.size(); ++i) memo.put(keys[i], static_cast<int>(10 * i));
  CHECK(memo.size() == keys.size());
  // The order they were put in (each the chained next of the one before),
  // twice, as a loop asks.
  for (int round = 0; round < 2; ++round)
    for (std::size_t i = 0; i < keys.size(); ++i) {
      const int* v = memo.find(keys[i]);
      REQUIRE(v);
      CHECK(*v == static_cast<int>(10 * i));
    }
  // Another order: the chained next is not the one asked for, the table answers.
  for (const std::size_t i : {4u, 0u, 2u, 2u, 1u, 3u, 0u}) {
    const int* v = memo.find(keys[i]);
    REQUIRE(v);
    CHECK(*v == static_cast<int>(10 * i));
  }
  CHECK_FALSE(memo.find({1, 2}));
  CHECK_FALSE(memo.find({9, 9, 9}));
}

TEST_CASE("a chained memory's put replaces, and a full one forgets everything at once", "[memo][base]") {
  rs::base::ChainedMemo<int> memo(3);
  memo.put({1}, 1);
  memo.put({2}, 2);
  REQUIRE(memo.find({1}));
  REQUIRE(memo.find({2}));  // {2} is now {1}'s chained next
  memo.put({2}, 20);        // in place: the chain to it still finds the new value
  REQUIRE(memo.find({1}));
  const int* two = memo.find({2});
  REQUIRE(two);
  CHECK(*two == 20);
  memo.put({3}, 3);
  CHECK(memo.size() == 3);
  memo.put({4}, 4);  // full: all forgotten, then {4} put
  CHECK(memo.size() == 1);
  // Nothing of before answers, neither through the table nor through a chain.
  CHECK_FALSE(memo.find({1}));
  CHECK_FALSE(memo.find({2}));
  CHECK_FALSE(memo.find({3}));
  const int* four = memo.find({4});
  REQUIRE(four);
  CHECK(*four == 4);
  memo.clear();
  CHECK(memo.size() == 0);
  CHECK_FALSE(memo.find({4}));
}

TEST_CASE("a chained memory answers a loop that goes one of two or three ways after the same entry", "[memo][base]") {
  rs::base::ChainedMemo<int> memo(16);
  memo.put({1}, 1);
  memo.put({2}, 2);
  memo.put({3}, 3);
  memo.put({4}, 4);
  // After {1}: {2}, then {3}, then {4}, round and round (more ways than an entry keeps followers for).
  for (int round = 0; round < 6; ++round)
    for (const std::uint64_t next : {2u, 3u, 4u, 3u}) {
      const int* one = memo.find({1});
      REQUIRE(one);
      CHECK(*one == 1);
      const int* v = memo.find({next});
      REQUIRE(v);
      CHECK(*v == static_cast<int>(next));
    }
  CHECK_FALSE(memo.find({5}));
}
