#include "serial_port.hpp"

#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <chrono>
#include <cstring>
#include <stdexcept>

namespace contour::board {

namespace {

speed_t speed_of(unsigned baud) {
  switch (baud) {
    case 9600: return B9600;
    case 19200: return B19200;
    case 38400: return B38400;
    case 57600: return B57600;
    case 115200: return B115200;
    case 230400: return B230400;
    case 460800: return B460800;
    case 500000: return B500000;
    case 921600: return B921600;
    case 1000000: return B1000000;
    case 2000000: return B2000000;
    case 3000000: return B3000000;
    case 4000000: return B4000000;
    default: return B0;
  }
}

std::string seconds(double s) {
  char b[32];
  std::snprintf(b, sizeof b, "%g s", s);
  return b;
}

std::string sys_error(const std::string& what) { return what + ": " + std::strerror(errno); }

void make_raw(int fd, speed_t speed) {
  termios tio{};
  if (tcgetattr(fd, &tio) != 0) return;  // not a terminal: nothing to set
  cfmakeraw(&tio);
  tio.c_cflag |= CLOCAL | CREAD;
  tio.c_cflag &= ~static_cast<tcflag_t>(CRTSCTS);
  tio.c_cc[VMIN] = 0;
  tio.c_cc[VTIME] = 0;
  if (speed != B0) {
    cfsetispeed(&tio, speed);
    cfsetospeed(&tio, speed);
  }
  tcsetattr(fd, TCSANOW, &tio);
}

}  // namespace

bool baud_supported(unsigned baud) { return speed_of(baud) != B0; }

SerialPort::SerialPort(const std::string& path, unsigned baud, double write_timeout_s)
    : path_(path), write_timeout_s_(write_timeout_s) {
  fd_ = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK);
  if (fd_ < 0) throw LinkError(sys_error("cannot open '" + path + "'"));
  make_raw(fd_, speed_of(baud));
}

SerialPort::~SerialPort() {
  if (fd_ >= 0) ::close(fd_);
}

void SerialPort::write(const Bytes& bytes) {
  std::size_t done = 0;
  double since = now_s();
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd_, bytes.data() + done, bytes.size() - done);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
      since = now_s();
    } else if (n < 0 && (errno == EAGAIN || errno == EINTR)) {
      if (now_s() - since > write_timeout_s_)
        throw LinkError("the board does not answer (nothing taken from the port for " + seconds(write_timeout_s_) + ")");
      pollfd p{fd_, POLLOUT, 0};
      ::poll(&p, 1, 10);
    } else {
      throw LinkError(sys_error("write to '" + path_ + "'"));
    }
  }
}

Bytes SerialPort::read(double timeout_s) {
  pollfd p{fd_, POLLIN, 0};
  const int r = ::poll(&p, 1, static_cast<int>(timeout_s * 1000));
  Bytes out;
  if (r <= 0) return out;
  if (p.revents & (POLLHUP | POLLERR)) throw LinkError("'" + path_ + "' hung up (the board went away)");
  std::uint8_t buf[4096];
  const ssize_t n = ::read(fd_, buf, sizeof buf);
  if (n > 0) out.assign(buf, buf + n);
  return out;
}

double SerialPort::now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

PtyMaster::PtyMaster() {
  fd_ = ::posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK);
  if (fd_ < 0 || ::grantpt(fd_) != 0 || ::unlockpt(fd_) != 0) throw std::runtime_error(sys_error("posix_openpt"));
  const char* name = ::ptsname(fd_);
  if (!name) throw std::runtime_error(sys_error("ptsname"));
  slave_ = name;
  // The slave raw from the start (no echo, no line editing), whoever opens it.
  const int s = ::open(name, O_RDWR | O_NOCTTY);
  if (s >= 0) {
    make_raw(s, B0);
    ::close(s);
  }
}

PtyMaster::~PtyMaster() {
  if (fd_ >= 0) ::close(fd_);
}

Bytes PtyMaster::read_some(bool& hangup) {
  hangup = false;
  std::uint8_t buf[4096];
  const ssize_t n = ::read(fd_, buf, sizeof buf);
  if (n > 0) return Bytes(buf, buf + n);
  if (n < 0 && errno == EIO) hangup = true;  // no slave open
  return {};
}

void PtyMaster::write_all(const Bytes& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd_, bytes.data() + done, bytes.size() - done);
    if (n > 0) done += static_cast<std::size_t>(n);
    else if (n < 0 && errno != EAGAIN && errno != EINTR) return;  // the host went away: its loss
    else {
      pollfd p{fd_, POLLOUT, 0};
      ::poll(&p, 1, 10);
    }
  }
}

void PtyMaster::wait_readable(double timeout_s) {
  pollfd p{fd_, POLLIN, 0};
  ::poll(&p, 1, static_cast<int>(timeout_s * 1000));
}

}  // namespace contour::board
