// The server's pieces below the protocol: UTF-16 positions, message framing, and the block
// around the cursor that completion reads from text which may not parse.
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "compiler/lsp/completion.h"
#include "compiler/lsp/json_rpc.h"
#include "compiler/lsp/text_document.h"

namespace sled::lsp {
namespace {

TEST(LineIndexTest, CountsColumnsInUtf16CodeUnits) {
  // `é` is 2 bytes and 1 unit; `😀` is 4 bytes and 2 units (a surrogate pair).
  const std::string text =
      "a\xC3\xA9\xF0\x9F\x98\x80"
      "b\r\nz";
  const LineIndex lines(text);
  EXPECT_EQ(lines.PositionOf(text, 1).character, 1u);
  EXPECT_EQ(lines.PositionOf(text, 3).character, 2u);
  EXPECT_EQ(lines.PositionOf(text, 7).character, 4u);
  EXPECT_EQ(lines.OffsetOf(text, {0, 4}), 7u);
  EXPECT_EQ(lines.OffsetOf(text, {0, 5}), 8u);
  // Past the line's end: before its line break (`\r\n` included); past the last line: the end.
  EXPECT_EQ(lines.OffsetOf(text, {0, 99}), 8u);
  EXPECT_EQ(lines.OffsetOf(text, {1, 0}), 10u);
  EXPECT_EQ(lines.OffsetOf(text, {7, 0}), text.size());
  const Position z = lines.PositionOf(text, 10);
  EXPECT_EQ(z.line, 1u);
  EXPECT_EQ(z.character, 0u);
}

TEST(TextDocumentTest, EditsApplyInOrderAndClampOutOfRangePositions) {
  TextDocument document("file:///x.sled", "abc\ndef\n", 1);
  document.Edit({{1, 1}, {1, 2}}, "EE");
  EXPECT_EQ(document.text(), "abc\ndEEf\n");
  document.Edit({{9, 9}, {0, 1}}, "|");  // reversed and past the end: the span between
  EXPECT_EQ(document.text(), "a|");
}

TEST(UriTest, FileUrisRoundTripWithEscapes) {
  EXPECT_EQ(PathOfUri("file:///tmp/a%20b/c.sled"), "/tmp/a b/c.sled");
  EXPECT_EQ(UriOfPath("/tmp/a b/c.sled"), "file:///tmp/a%20b/c.sled");
  EXPECT_EQ(PathOfUri("file://localhost/tmp/c.sled"), "/tmp/c.sled");
}

TEST(ReadMessageTest, ReadsFramedBodiesAndSkipsBadHeaders) {
  std::istringstream in(
      "Content-Length: 2\r\n\r\n{}"
      "Content-Length: x\r\n\r\n"
      "Content-Type: utf-8\r\ncontent-length: 4\r\n\r\n[1,2]");
  IncomingMessage first = ReadMessage(in);
  ASSERT_EQ(first.status, IncomingMessage::Status::kOk);
  EXPECT_EQ(first.body, "{}");
  EXPECT_EQ(ReadMessage(in).status, IncomingMessage::Status::kBadHeader);
  IncomingMessage third = ReadMessage(in);
  ASSERT_EQ(third.status, IncomingMessage::Status::kOk);
  EXPECT_EQ(third.body, "[1,2");
  // What is left (`]`) is a header line that never ends: a bad header at the end of input.
  EXPECT_EQ(ReadMessage(in).status, IncomingMessage::Status::kBadHeader);
  EXPECT_EQ(ReadMessage(in).status, IncomingMessage::Status::kEnd);
}

TEST(ReadMessageTest, ATruncatedBodyIsReportedNotReturned) {
  std::istringstream in("Content-Length: 100\r\n\r\n{\"short\":1}");
  const IncomingMessage message = ReadMessage(in);
  EXPECT_EQ(message.status, IncomingMessage::Status::kBadHeader);
  EXPECT_TRUE(message.body.empty());
}

TEST(BlockChainTest, FollowsBracesSkippingCommentsAndStrings) {
  const std::string text =
      "scenario \"a { b\" {\n"
      "  // a comment {\n"
      "  body dummy {\n"
      "    segment s { mass = 1 kg }\n"
      "    segment t {\n"
      "      ";
  const BlockChain chain = BlockChainAt(text, static_cast<std::uint32_t>(text.size()));
  ASSERT_EQ(chain.keywords, (std::vector<std::string>{"scenario", "body", "segment"}));
  ASSERT_TRUE(chain.kind.has_value());
  EXPECT_EQ(*chain.kind, compiler::BlockKind::kSegment);
}

TEST(BlockChainTest, ATableAttributeOpensATableBlock) {
  const std::string text = "scenario \"a\" {\n  function foam = table(deflection -> force) {\n  ";
  const BlockChain chain = BlockChainAt(text, static_cast<std::uint32_t>(text.size()));
  ASSERT_TRUE(chain.kind.has_value());
  EXPECT_EQ(*chain.kind, compiler::BlockKind::kTable);
  const std::string unknown = "scenario \"a\" {\n  nonsense {\n  ";
  EXPECT_FALSE(BlockChainAt(unknown, static_cast<std::uint32_t>(unknown.size())).kind);
}

}  // namespace
}  // namespace sled::lsp
