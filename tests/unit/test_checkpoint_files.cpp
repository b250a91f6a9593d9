// Checkpoints: the marker's bookkeeping (which file is newest and complete, which slot is next) and
// the CSV rows a resumed run keeps.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "crush_checkpoint_files.h"
#include "crush_csv_rows.h"
#include "crush_model_error.h"

using namespace crush;

namespace {
CheckpointEntry entry(long long step, long long bytes, const std::string &file)
{
  CheckpointEntry e;
  e.step = step;
  e.bytes = bytes;
  e.file = file;
  return e;
}
}  // namespace

TEST(CheckpointFiles, MarkerRoundTripsWithVariables)
{
  CheckpointEntry b = entry(40000, 2812416, "ckpt_O2.1.restart");
  b.variables = {{"H0", "0.0039871234567891234"}, {"V0", "6.2e-08"}};
  const std::string text = format_marker({entry(20000, 2811904, "ckpt_O2.2.restart"), b});
  const std::vector<CheckpointEntry> back = parse_marker(text);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[0].step, 20000);
  EXPECT_EQ(back[0].bytes, 2811904);
  EXPECT_EQ(back[0].file, "ckpt_O2.2.restart");
  EXPECT_TRUE(back[0].variables.empty());
  EXPECT_EQ(back[1].variables, b.variables);
}

TEST(CheckpointFiles, MalformedMarkersNameTheLine)
{
  EXPECT_THROW(parse_marker("20000 12 a.restart\nnot a line\n"), ModelError);
  try {
    parse_marker("# title\n20000 -5 a.restart\n");
    FAIL();
  } catch (const ModelError &e) {
    EXPECT_NE(std::string(e.what()).find("line 2"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse_marker("20000 12 a.restart H0\n"), ModelError);
  EXPECT_THROW(parse_marker("2e4 12 a.restart\n"), ModelError);
}

// The slots alternate, and the marker keeps the other slot's entry: one complete file always exists.
TEST(CheckpointFiles, SlotsAlternate)
{
  std::vector<CheckpointEntry> list;
  EXPECT_EQ(next_slot("c", list), 1);
  list = after_write("c", list, entry(100, 10, checkpoint_file("c", 1)));
  EXPECT_EQ(next_slot("c", list), 2);
  list = after_write("c", list, entry(200, 11, checkpoint_file("c", 2)));
  ASSERT_EQ(list.size(), 2u);
  EXPECT_EQ(list[0].file, "c.1.restart");
  EXPECT_EQ(list[1].file, "c.2.restart");
  EXPECT_EQ(next_slot("c", list), 1);
  list = after_write("c", list, entry(300, 12, checkpoint_file("c", 1)));
  ASSERT_EQ(list.size(), 2u);
  EXPECT_EQ(list[0].step, 200);
  EXPECT_EQ(list[1].step, 300);
  EXPECT_EQ(checkpoint_marker("c"), "c.last");
}

// Complete: the file exists with the size recorded. A newest file cut short falls back to the other.
TEST(CheckpointFiles, NewestCompleteChecksTheSize)
{
  const std::vector<CheckpointEntry> list = {entry(200, 11, "c.2.restart"), entry(300, 12, "c.1.restart")};
  std::map<std::string, long long> sizes = {{"c.2.restart", 11}, {"c.1.restart", 12}};
  auto size_of = [&](const std::string &f) { return sizes.count(f) ? sizes[f] : -1LL; };
  EXPECT_EQ(newest_complete(list, size_of), 1);
  sizes["c.1.restart"] = 7;  // truncated
  EXPECT_EQ(newest_complete(list, size_of), 0);
  sizes.erase("c.2.restart");
  EXPECT_EQ(newest_complete(list, size_of), -1);
}

TEST(CsvRows, TrimKeepsTitleAndRowsUpToTheStep)
{
  const std::string csv = "step,a\n100,1\n200,2\n300,3\n400,4";  // the last row cut short
  int dropped = 0;
  EXPECT_EQ(trim_rows(csv, 200, false, dropped), "step,a\n100,1\n200,2\n");
  EXPECT_EQ(dropped, 2);
  EXPECT_EQ(trim_rows(csv, 200, true, dropped), "step,a\n100,1\n");
  EXPECT_EQ(dropped, 3);
  EXPECT_EQ(trim_rows("# comment\nstep\n", 0, true, dropped), "# comment\nstep\n");
  EXPECT_EQ(dropped, 0);
  EXPECT_EQ(trim_rows("", 10, false, dropped), "");
}
