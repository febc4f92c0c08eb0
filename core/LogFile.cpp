#include "core/LogFile.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iostream>
#include <memory>
#include <mutex>
#include <streambuf>

#include "core/OpenSeesError.h"

namespace beamsolid {

namespace {

// Writes each character to the file and, when echoing, to the original buffer.
class TeeBuffer : public std::streambuf {
 public:
  TeeBuffer(std::streambuf* terminal, std::ofstream file, bool echo)
      : terminal_(terminal), file_(std::move(file)), echo_(echo) {}
  std::streambuf* terminal() const { return terminal_; }

 protected:
  int overflow(int c) override {
    if (c == traits_type::eof()) return traits_type::not_eof(c);
    file_.put(static_cast<char>(c));
    if (echo_) terminal_->sputc(static_cast<char>(c));
    return c;
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    file_.write(s, n);
    if (echo_) terminal_->sputn(s, n);
    return n;
  }
  int sync() override {
    file_.flush();
    return echo_ ? terminal_->pubsync() : 0;
  }

 private:
  std::streambuf* terminal_;
  std::ofstream file_;
  bool echo_;
};

std::mutex gMutex;
std::unique_ptr<TeeBuffer> gTee;

void closeLocked() {
  if (!gTee) return;
  std::cerr.flush();
  std::cerr.rdbuf(gTee->terminal());
  gTee.reset();
}

struct CloseAtExit {
  ~CloseAtExit() {
    std::lock_guard<std::mutex> lock(gMutex);
    closeLocked();
  }
} gCloseAtExit;

}  // namespace

void LogFile::open(const std::string& path, bool append, bool echo) {
  std::ofstream file(path, append ? std::ios::app : std::ios::trunc);
  if (!file) throw OpenSeesError("cannot open '" + path + "' for writing (" + std::strerror(errno) + ")");
  std::lock_guard<std::mutex> lock(gMutex);
  closeLocked();
  gTee = std::make_unique<TeeBuffer>(std::cerr.rdbuf(), std::move(file), echo);
  std::cerr.rdbuf(gTee.get());
}

void LogFile::close() {
  std::lock_guard<std::mutex> lock(gMutex);
  closeLocked();
}

}  // namespace beamsolid
