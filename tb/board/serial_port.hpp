// Serial ports for the link, POSIX: the host's end (a tty such as
// /dev/ttyUSB1 or a pty's slave, raw 8N1 at a baud rate) and the
// simulated board's end (a pty master, whose slave's path the host opens).
#pragma once

#include <string>

#include "link_client.hpp"

namespace contour::board {

// The host's port. Throws LinkError if it cannot be opened or set up, or
// when a write makes no progress for `write_timeout_s` (nobody reads).
class SerialPort : public Transport {
 public:
  SerialPort(const std::string& path, unsigned baud, double write_timeout_s = 5);
  ~SerialPort() override;
  SerialPort(const SerialPort&) = delete;
  SerialPort& operator=(const SerialPort&) = delete;
  void write(const Bytes& bytes) override;
  Bytes read(double timeout_s) override;
  double now_s() override;

 private:
  int fd_ = -1;
  std::string path_;
  double write_timeout_s_;
};

// A pseudo-terminal's master, raw, non-blocking.
class PtyMaster {
 public:
  PtyMaster();  // throws std::runtime_error
  ~PtyMaster();
  PtyMaster(const PtyMaster&) = delete;
  PtyMaster& operator=(const PtyMaster&) = delete;
  const std::string& slave_path() const { return slave_; }
  // What the host has written; `hangup` is set when no one holds the slave open.
  Bytes read_some(bool& hangup);
  void write_all(const Bytes& bytes);
  // Waits up to `timeout_s` for the host to write.
  void wait_readable(double timeout_s);

 private:
  int fd_ = -1;
  std::string slave_;
};

// Whether `baud` is one the port can be set to (B9600 ... B4000000).
bool baud_supported(unsigned baud);

}  // namespace contour::board
