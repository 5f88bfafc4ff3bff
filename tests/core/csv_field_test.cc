#include "core/csv_field.h"

#include <gtest/gtest.h>

namespace novelty::core {
namespace {

TEST(CsvField, PlainTextStaysAsItIs) {
  EXPECT_EQ(CsvField("AUC"), "AUC");
  EXPECT_EQ(CsvField(""), "");
  EXPECT_EQ(CsvField("81.5 % (thesis)"), "81.5 % (thesis)");
}

// RFC 4180, 2.6 and 2.7: fields with commas, quotes or line breaks are quoted, quotes doubled.
TEST(CsvField, CommasQuotesAndLineBreaksAreQuoted) {
  EXPECT_EQ(CsvField("TPR at FPR <= 1 %, matches"), "\"TPR at FPR <= 1 %, matches\"");
  EXPECT_EQ(CsvField("the \"cup\""), "\"the \"\"cup\"\"\"");
  EXPECT_EQ(CsvField("a\nb"), "\"a\nb\"");
  EXPECT_EQ(CsvField("a\rb"), "\"a\rb\"");
  EXPECT_EQ(CsvField("\""), "\"\"\"\"");
}

}  // namespace
}  // namespace novelty::core
