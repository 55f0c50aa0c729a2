#include "compiler/lsp/json_rpc.h"

#include <cctype>
#include <charconv>
#include <string_view>

namespace sled::lsp {
namespace {

// Reads one header line up to "\r\n" (a bare "\n" is accepted too); false at the end of input.
bool ReadHeaderLine(std::istream& in, std::string& line) {
  line.clear();
  constexpr std::size_t kMaxHeaderLine = 4096;
  for (int c = in.get(); c != std::char_traits<char>::eof(); c = in.get()) {
    if (c == '\n') {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      return true;
    }
    if (line.size() < kMaxHeaderLine) line.push_back(static_cast<char>(c));
  }
  return !line.empty();
}

bool StartsWithNoCase(std::string_view text, std::string_view prefix) {
  if (text.size() < prefix.size()) return false;
  for (std::size_t i = 0; i < prefix.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(text[i])) !=
        std::tolower(static_cast<unsigned char>(prefix[i]))) {
      return false;
    }
  }
  return true;
}

}  // namespace

IncomingMessage ReadMessage(std::istream& in) {
  IncomingMessage message;
  std::string line;
  std::optional<std::size_t> length;
  bool any_header = false;
  bool bad_length = false;
  while (true) {
    if (!ReadHeaderLine(in, line)) {
      // The input ended: between messages that is the normal end; inside a header it is not.
      message.status =
          any_header ? IncomingMessage::Status::kBadHeader : IncomingMessage::Status::kEnd;
      message.problem = "the input ended inside a message header";
      if (!any_header) message.problem.clear();
      return message;
    }
    if (line.empty()) {
      if (any_header) break;
      continue;  // stray blank lines between messages
    }
    any_header = true;
    constexpr std::string_view kLength = "content-length:";
    if (StartsWithNoCase(line, kLength)) {
      std::string_view value = std::string_view(line).substr(kLength.size());
      while (!value.empty() && (value.front() == ' ' || value.front() == '\t')) {
        value.remove_prefix(1);
      }
      while (!value.empty() && (value.back() == ' ' || value.back() == '\t')) {
        value.remove_suffix(1);
      }
      std::size_t parsed = 0;
      const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), parsed);
      if (error != std::errc() || end != value.data() + value.size() || value.empty()) {
        bad_length = true;
      } else {
        length = parsed;
      }
    }
    // Other headers (Content-Type) are allowed and ignored.
  }
  if (bad_length || !length) {
    message.status = IncomingMessage::Status::kBadHeader;
    message.problem = "a message header without a valid Content-Length";
    return message;
  }
  if (*length > kMaxMessageBytes) {
    message.status = IncomingMessage::Status::kBadHeader;
    message.problem = "a message larger than 256 MiB";
    // Skip the body so the next message can still be read.
    in.ignore(static_cast<std::streamsize>(*length));
    return message;
  }
  message.body.resize(*length);
  in.read(message.body.data(), static_cast<std::streamsize>(*length));
  if (static_cast<std::size_t>(in.gcount()) != *length) {
    message.status = IncomingMessage::Status::kBadHeader;
    message.problem = "the input ended inside a message body";
    message.body.clear();
    return message;
  }
  message.status = IncomingMessage::Status::kOk;
  return message;
}

void WriteMessage(std::ostream& out, const std::string& body) {
  out << "Content-Length: " << body.size() << "\r\n\r\n" << body;
  out.flush();
}

}  // namespace sled::lsp
