#include "lab/csv_table.h"

#include <gtest/gtest.h>

#include <cmath>

namespace prt {
namespace {

TEST(CsvTable, WritesHeaderAndRows) {
  CsvTable t({"case", "seconds"});
  t.addRow({"A", "1.5"});
  t.addRow({"B", "3"});
  EXPECT_EQ(t.text(), "case,seconds\nA,1.5\nB,3\n");
  EXPECT_EQ(t.column("seconds"), 1u);
}

TEST(CsvTable, QuotesCellsWithCommasQuotesAndLineBreaks) {
  CsvTable t({"note"});
  t.addRow({"a,b"});
  t.addRow({"say \"hi\""});
  t.addRow({"two\nlines"});
  EXPECT_EQ(t.text(), "note\n\"a,b\"\n\"say \"\"hi\"\"\"\n\"two\nlines\"\n");
}

TEST(CsvTable, NumbersAreShortAndMissingValuesEmpty) {
  EXPECT_EQ(csvNumber(0.5), "0.5");
  EXPECT_EQ(csvNumber(2.0), "2");
  EXPECT_EQ(csvNumber(1.23456789, 4), "1.235");
  EXPECT_EQ(csvNumber(std::nan("")), "");
  EXPECT_EQ(csvNumber(INFINITY), "");
}

}  // namespace
}  // namespace prt
