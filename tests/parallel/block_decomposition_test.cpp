// The blocks of whole z-planes and their deal to processes (core/parallel/block_decomposition.hpp).
#include "parallel/block_decomposition.hpp"
#include "common/errors.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace rbcsim::parallel {
namespace {

TEST(BlockDecomposition, EqualBlocksAreDealtInOrder) {
  const BlockDecomposition blocks(12, 2, 3);
  EXPECT_EQ(blocks.block_count(), 6);
  EXPECT_EQ(blocks.rank_count(), 3);
  for (int rank = 0; rank < 3; ++rank) {
    EXPECT_EQ(blocks.z_begin(rank), 4 * rank);
    EXPECT_EQ(blocks.z_end(rank), 4 * rank + 4);
  }
  EXPECT_EQ(blocks.owner_of_plane(0), 0);
  EXPECT_EQ(blocks.owner_of_plane(7), 1);
  EXPECT_EQ(blocks.owner_of_plane(11), 2);
}

TEST(BlockDecomposition, TheBlocksDoNotDependOnTheProcessCount) {
  for (int ranks = 1; ranks <= 4; ++ranks) {
    const BlockDecomposition blocks(14, 4, ranks);
    ASSERT_EQ(blocks.block_count(), 4);  // 0, 4, 8, 12 and a last block of 2 planes
    EXPECT_EQ(blocks.block_z_begin(3), 12);
    EXPECT_EQ(blocks.z_end(ranks - 1), 14);
  }
  // A remainder thinner than the halo joins the block before it.
  const BlockDecomposition merged(13, 4, 1);
  EXPECT_EQ(merged.block_count(), 3);
  EXPECT_EQ(merged.block_z_begin(2), 8);
  EXPECT_EQ(merged.z_end(0), 13);
}

TEST(BlockDecomposition, WeightsMoveTheCut) {
  // Half of the weight in the first block: it is rank 0's alone.
  const std::vector<std::int64_t> weights = {3, 1, 1, 1};
  const BlockDecomposition blocks(8, 2, 2, weights);
  EXPECT_EQ(blocks.first_block(1), 1);
  EXPECT_EQ(blocks.z_end(0), 2);
  // Without weights the cut is in the middle.
  EXPECT_EQ(BlockDecomposition(8, 2, 2).first_block(1), 2);
}

TEST(BlockDecomposition, EveryProcessGetsABlockEvenWithoutWeight) {
  const std::vector<std::int64_t> weights = {0, 0, 5, 0, 0};
  const BlockDecomposition blocks(10, 2, 4, weights);
  for (int rank = 0; rank < 4; ++rank) {
    EXPECT_LT(blocks.first_block(rank), blocks.first_block(rank + 1)) << "rank " << rank;
  }
  EXPECT_EQ(blocks.first_block(4), 5);
}

TEST(BlockDecomposition, RefusesWhatCannotBeDealt) {
  try {
    BlockDecomposition(8, 4, 3);
    FAIL() << "2 blocks for 3 processes accepted";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("2 block(s) for 3 processes"), std::string::npos) << message;
  }
  EXPECT_THROW(BlockDecomposition(8, 1, 1), InputError);
  const std::vector<std::int64_t> wrong_count = {1, 1};
  EXPECT_THROW(BlockDecomposition(8, 2, 1, wrong_count), InputError);
}

}  // namespace
}  // namespace rbcsim::parallel
