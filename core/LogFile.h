#pragma once
#include <string>

namespace beamsolid {

// logFile(fileName, <'-append'>, <'-noEcho'>): everything BeamSolid writes to
// std::cerr (warnings, analyze failures, timers) also goes to the file, as
// OpenSees' log file; -noEcho keeps it off the terminal. Process-wide, like
// the stream it copies; a new logFile replaces the previous one.
class LogFile {
 public:
  static void open(const std::string& path, bool append, bool echo);
  // Restores std::cerr and closes the file (at exit, or for tests).
  static void close();
};

}  // namespace beamsolid
