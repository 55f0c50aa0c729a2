// A Language Server Protocol client for the tests: starts `sled lsp` with two pipes and speaks
// the protocol to it (framing written here, independently of the server's), so the tests see
// exactly what an editor would.
#pragma once

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <poll.h>

#include <nlohmann/json.hpp>

namespace sled::testing {

using Json = nlohmann::json;

class LspClient {
 public:
  explicit LspClient(std::vector<std::string> arguments = {}) {
    int to_server[2];
    int from_server[2];
    if (pipe(to_server) != 0 || pipe(from_server) != 0) return;
    pid_ = fork();
    if (pid_ == 0) {
      dup2(to_server[0], 0);
      dup2(from_server[1], 1);
      close(to_server[1]);
      close(from_server[0]);
      std::vector<std::string> words = {SLED_BINARY, "lsp"};
      words.insert(words.end(), arguments.begin(), arguments.end());
      std::vector<char*> argv;
      argv.reserve(words.size() + 1);
      for (std::string& word : words) argv.push_back(word.data());
      argv.push_back(nullptr);
      execv(argv[0], argv.data());
      _exit(127);
    }
    close(to_server[0]);
    close(from_server[1]);
    in_ = to_server[1];
    out_ = from_server[0];
    signal(SIGPIPE, SIG_IGN);
  }

  ~LspClient() {
    if (in_ >= 0) close(in_);
    if (out_ >= 0) close(out_);
    if (pid_ > 0 && !exit_code_) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
  }

  bool started() const { return pid_ > 0; }

  void SendRaw(const std::string& bytes) {
    std::size_t sent = 0;
    while (sent < bytes.size()) {
      const ssize_t n = write(in_, bytes.data() + sent, bytes.size() - sent);
      if (n <= 0) return;
      sent += static_cast<std::size_t>(n);
    }
  }

  void SendBody(const std::string& body) {
    SendRaw("Content-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body);
  }

  void Notify(const std::string& method, Json params) {
    SendBody(Json{{"jsonrpc", "2.0"}, {"method", method}, {"params", std::move(params)}}.dump());
  }

  // Sends a request and returns its response, keeping the notifications that came before it.
  Json Request(const std::string& method, Json params) {
    const int id = ++last_id_;
    SendBody(Json{{"jsonrpc", "2.0"}, {"id", id}, {"method", method}, {"params", std::move(params)}}
                 .dump());
    return AwaitResponse(id);
  }

  Json AwaitResponse(const Json& id) {
    for (std::size_t i = 0; i < notifications_.size(); ++i) {
      if (notifications_[i].value("id", Json()) == id && !notifications_[i].contains("method")) {
        Json found = notifications_[i];
        notifications_.erase(notifications_.begin() + static_cast<std::ptrdiff_t>(i));
        return found;
      }
    }
    while (auto message = Next()) {
      if (message->contains("id") && (*message)["id"] == id && !message->contains("method")) {
        return *message;
      }
      notifications_.push_back(std::move(*message));
    }
    ADD_FAILURE() << "no response to request " << id.dump();
    return Json();
  }

  // The next publishDiagnostics for `uri` (from those received, else waits for one).
  Json AwaitDiagnostics(const std::string& uri) {
    for (std::size_t i = 0; i < notifications_.size(); ++i) {
      if (IsDiagnosticsFor(notifications_[i], uri)) {
        Json found = notifications_[i];
        notifications_.erase(notifications_.begin() + static_cast<std::ptrdiff_t>(i));
        return found["params"];
      }
    }
    while (auto message = Next()) {
      if (IsDiagnosticsFor(*message, uri)) return (*message)["params"];
      notifications_.push_back(std::move(*message));
    }
    ADD_FAILURE() << "no diagnostics for " << uri;
    return Json();
  }

  // Closes the server's input and waits for it to end; its exit code (-1 when killed).
  int CloseAndWait() {
    if (in_ >= 0) close(in_);
    in_ = -1;
    int status = 0;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (waitpid(pid_, &status, WNOHANG) == 0) {
      if (std::chrono::steady_clock::now() > deadline) {
        kill(pid_, SIGKILL);
        waitpid(pid_, &status, 0);
        break;
      }
      usleep(10000);
    }
    exit_code_ = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return *exit_code_;
  }

  std::vector<Json>& notifications() { return notifications_; }

 private:
  static bool IsDiagnosticsFor(const Json& message, const std::string& uri) {
    return message.value("method", "") == "textDocument/publishDiagnostics" &&
           message["params"].value("uri", "") == uri;
  }

  // Reads one framed message, within 30 s; nullopt at the end of output or on a framing error.
  std::optional<Json> Next() {
    std::string header;
    while (header.find("\r\n\r\n") == std::string::npos) {
      char c;
      if (!ReadExactly(&c, 1)) return std::nullopt;
      header.push_back(c);
    }
    const std::size_t at = header.find("Content-Length: ");
    if (at == std::string::npos) return std::nullopt;
    const std::size_t length = std::stoul(header.substr(at + 16));
    std::string body(length, '\0');
    if (!ReadExactly(body.data(), length)) return std::nullopt;
    Json message = Json::parse(body, nullptr, false);
    if (message.is_discarded()) return std::nullopt;
    return message;
  }

  bool ReadExactly(char* data, std::size_t size) {
    std::size_t got = 0;
    while (got < size) {
      pollfd ready{out_, POLLIN, 0};
      if (poll(&ready, 1, 30000) <= 0) return false;
      const ssize_t n = read(out_, data + got, size - got);
      if (n <= 0) {
        if (n < 0 && errno == EINTR) continue;
        return false;
      }
      got += static_cast<std::size_t>(n);
    }
    return true;
  }

  pid_t pid_ = -1;
  int in_ = -1;
  int out_ = -1;
  int last_id_ = 0;
  std::optional<int> exit_code_;
  std::vector<Json> notifications_;
};

}  // namespace sled::testing
