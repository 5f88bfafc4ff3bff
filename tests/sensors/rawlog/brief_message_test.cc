#include "sensors/rawlog/brief_message.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace novelty::sensors {
namespace {

TEST(BriefMessage, KeepsOurPrefixAndMrptsMessagesOnOneLine) {
  const std::string mrpt =
      "f.rawlog: cannot read object 40: ==== MRPT exception ====\n"
      "Message:  Exception while parsing typed object 'CObservationBearingRange'\n"
      "Location: /build/mrpt/CArchive.cpp:123: readObject\n"
      "Call stack backtrace:\n"
      "[0x7f] mrpt::serialization::CArchive::ReadObject()\n"
      "==== MRPT exception ====\n"
      "Message:  Unexpected end of file\n"
      "Location: somewhere\n";
  EXPECT_EQ(BriefMessage(std::runtime_error(mrpt)),
            "f.rawlog: cannot read object 40: Exception while parsing typed object "
            "'CObservationBearingRange': Unexpected end of file");
}

// A message MRPT split at its '[': the text is in the Location line.
TEST(BriefMessage, AMessageMrptTookForALocationIsKept) {
  const std::string mrpt =
      "f.rawlog: frame 1 (RGBD): ==== MRPT exception ====\n"
      "Message: \n"
      "Location: filesystem error: cannot get file size: No such file [x/000001_depth.bin\n"
      "Call stack backtrace:\n"
      "[0 ]     0x7f12265c3b19\n";
  EXPECT_EQ(BriefMessage(mrpt),
            "f.rawlog: frame 1 (RGBD): filesystem error: cannot get file size: No such file "
            "[x/000001_depth.bin");
}

TEST(BriefMessage, PlainTextStaysAndBinaryBytesAreMasked) {
  EXPECT_EQ(BriefMessage(std::string("no such rawlog")), "no such rawlog");
  EXPECT_EQ(BriefMessage(std::string("class <\x01\xff> x\ny")),
            "class <?"
            "?> x y");
  EXPECT_EQ(BriefMessage(std::string(500, 'a'), 10), std::string(10, 'a') + "…");
  // UTF-8 stays (the programs' own messages use it); a cut never splits a character, and a
  // lone continuation or truncated sequence is masked.
  EXPECT_EQ(BriefMessage(std::string("need 2…512 hypotheses")), "need 2…512 hypotheses");
  EXPECT_EQ(BriefMessage(std::string("ab…"), 3), "ab…");
  EXPECT_EQ(BriefMessage(std::string("x\x80y\xe2\x80")), "x?y??");
}

}  // namespace
}  // namespace novelty::sensors
