// The nesting scan readDeck runs before Teuchos parses a deck: what it counts
// and what it skips, and readDeck at the limit and one level past it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "cgcm/core/Error.hpp"
#include "cgcm/io/Deck.hpp"

namespace cgcm::io {
namespace {

// `levels` nested <ParameterList name="lN">, the innermost holding one parameter.
std::string nested(int levels) {
  std::string open, close;
  for (int k = 0; k < levels; ++k) {
    open += "<ParameterList name=\"l" + std::to_string(k) + "\">";
    close = "</ParameterList>" + close;
  }
  return open + "<Parameter name=\"x\" type=\"double\" value=\"1\"/>" + close + "\n";
}

std::string writeFile(const std::string& name, const std::string& text) {
  const std::string dir = std::string(CGCM_TEST_OUTPUT) + "/xml-nesting";
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/" + name;
  std::ofstream(path) << text;
  return path;
}

TEST(XmlNesting, CountsElements) {
  EXPECT_EQ(xmlNestingDepth(""), 0);
  EXPECT_EQ(xmlNestingDepth("no markup"), 0);
  EXPECT_EQ(xmlNestingDepth("<a/>"), 0);  // self-closing: no level
  EXPECT_EQ(xmlNestingDepth("<a></a>"), 1);
  EXPECT_EQ(xmlNestingDepth("<a><b/><c><d></d></c></a>"), 3);
  EXPECT_EQ(xmlNestingDepth("<a>\n  <b>\n  </b>\n  <b></b>\n</a>"), 2);  // siblings do not add up
  EXPECT_EQ(xmlNestingDepth(nested(3)), 3);
}

TEST(XmlNesting, SkipsCommentsCdataInstructionsAndQuotedValues) {
  EXPECT_EQ(xmlNestingDepth("<?xml version=\"1.0\"?><a></a>"), 1);
  EXPECT_EQ(xmlNestingDepth("<a><!-- <b><c><d> --></a>"), 1);
  EXPECT_EQ(xmlNestingDepth("<a><!-- a comment with > and -- <b> --><b/></a>"), 1);
  EXPECT_EQ(xmlNestingDepth("<a><![CDATA[<b><c><d>]]></a>"), 1);
  EXPECT_EQ(xmlNestingDepth("<a><![CDATA[ ]> <b> ]]><b></b></a>"), 2);
  EXPECT_EQ(xmlNestingDepth("<a><?pi <b><c> ?></a>"), 1);
  EXPECT_EQ(xmlNestingDepth("<!DOCTYPE a [ <!ELEMENT a ANY> <!ENTITY e \"<b>\"> ]><a></a>"), 1);
  EXPECT_EQ(xmlNestingDepth("<a v=\"x > y\"><b w='<c>' u=\"/\"></b></a>"), 2);
  EXPECT_EQ(xmlNestingDepth("<a v=\"x/>\"></a>"), 1);  // the '/' before '>' is in the value
}

TEST(XmlNesting, StopsPastTheLimit) {
  EXPECT_EQ(xmlNestingDepth(nested(kMaxDeckNesting - 1)), kMaxDeckNesting - 1);
  EXPECT_EQ(xmlNestingDepth(nested(kMaxDeckNesting)), kMaxDeckNesting);
  EXPECT_EQ(xmlNestingDepth(nested(kMaxDeckNesting + 1)), kMaxDeckNesting + 1);
  EXPECT_EQ(xmlNestingDepth(nested(10), 4), 5);
  EXPECT_EQ(xmlNestingDepth(std::string(100000, '<') + "a>"), 1);  // malformed: left to the parser
  std::string deep;
  for (int k = 0; k < 100000; ++k) deep += "<a>";
  EXPECT_EQ(xmlNestingDepth(deep), kMaxDeckNesting + 1);
}

TEST(XmlNesting, ReadDeckAcceptsTheLimitAndRefusesOneMore) {
  const std::string atLimit = writeFile("at-limit.xml", nested(kMaxDeckNesting));
  const auto deck = readDeck(atLimit);
  EXPECT_TRUE(deck->isSublist("l1"));
  const std::string past = writeFile("past-limit.xml", nested(kMaxDeckNesting + 1));
  try {
    readDeck(past);
    FAIL() << "a deck nested " << kMaxDeckNesting + 1 << " deep accepted";
  } catch (const InputError& e) {
    const std::string why = e.what();
    EXPECT_NE(why.find("\"" + past + "\""), std::string::npos) << why;
    EXPECT_NE(why.find("more than " + std::to_string(kMaxDeckNesting) + " levels deep"), std::string::npos) << why;
  }
  // nesting inside a comment is not counted
  const std::string commented =
      writeFile("commented.xml", "<ParameterList name=\"cgcm\"><!--" + nested(2 * kMaxDeckNesting) + "--></ParameterList>");
  EXPECT_NO_THROW(readDeck(commented));
}

}  // namespace
}  // namespace cgcm::io
