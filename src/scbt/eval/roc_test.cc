#include "scbt/eval/roc.h"

#include <gtest/gtest.h>

#include <random>

namespace scbt {
namespace {

TEST(RocAucTest, PerfectInvertedAndUninformativeScores) {
  EXPECT_DOUBLE_EQ(*roc_auc({0.1, 0.2, 0.8, 0.9}, {false, false, true, true}), 1.0);
  EXPECT_DOUBLE_EQ(*roc_auc({0.9, 0.8, 0.2, 0.1}, {false, false, true, true}), 0.0);
  EXPECT_DOUBLE_EQ(*roc_auc({0.5, 0.5, 0.5, 0.5}, {false, true, false, true}), 0.5);
  // One of four positive-negative pairs is ranked wrong.
  EXPECT_DOUBLE_EQ(*roc_auc({0.1, 0.6, 0.5, 0.9}, {false, false, true, true}), 0.75);
}

TEST(RocAucTest, NothingToRankWithoutBothClasses) {
  EXPECT_FALSE(roc_auc({0.1, 0.2}, {true, true}).has_value());
  EXPECT_FALSE(roc_auc({}, {}).has_value());
  EXPECT_THROW(roc_auc({0.1}, {true, false}), std::invalid_argument);
}

// Against counting every pair, on random scores with many ties.
TEST(RocAucTest, MatchesPairCountingOnRandomTiedScores) {
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> level(0, 9);
  std::bernoulli_distribution coin(0.3);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<double> scores;
    std::vector<bool> positive;
    for (int i = 0; i < 60; ++i) {
      scores.push_back(level(rng));
      positive.push_back(coin(rng));
    }
    double wins = 0.0, pairs = 0.0;
    for (size_t i = 0; i < scores.size(); ++i) {
      for (size_t j = 0; j < scores.size(); ++j) {
        if (!positive[i] || positive[j]) continue;
        pairs += 1.0;
        wins += scores[i] > scores[j] ? 1.0 : scores[i] == scores[j] ? 0.5 : 0.0;
      }
    }
    const std::optional<double> auc = roc_auc(scores, positive);
    if (pairs == 0.0) {
      EXPECT_FALSE(auc.has_value());
    } else {
      EXPECT_NEAR(*auc, wins / pairs, 1e-12);
    }
  }
}

}  // namespace
}  // namespace scbt
