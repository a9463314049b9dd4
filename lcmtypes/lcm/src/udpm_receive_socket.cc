#include "dream/lcm/udpm_receive_socket.h"

#include <dirent.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/stat.h>

#include <cstdlib>
#include <map>

namespace dream::lcm {

namespace {

// Socket inodes by descriptor; an inode names a socket while it is open, so
// a descriptor number reused meanwhile is not mistaken for an old socket.
std::map<int, ino_t> OpenSockets() {
  std::map<int, ino_t> sockets;
  // libc's readdir rather than std::filesystem: every agent process runs
  // this, and the latter maps pages of libstdc++ nothing else there uses.
  DIR* folder = opendir("/proc/self/fd");
  if (folder == nullptr) return sockets;
  const int own = dirfd(folder);
  // Bounded: a process has at most its descriptor limit open.
  while (const dirent* entry = readdir(folder)) {
    char* end = nullptr;
    const long fd = std::strtol(entry->d_name, &end, 10);
    if (end == entry->d_name || *end != '\0' || fd < 0 || fd == own) continue;
    struct stat info {};
    if (fstat(static_cast<int>(fd), &info) == 0 && S_ISSOCK(info.st_mode)) sockets[static_cast<int>(fd)] = info.st_ino;
  }
  closedir(folder);
  return sockets;
}

bool IsUdpBoundTo(int fd, int port) {
  int type = 0;
  socklen_t length = sizeof(type);
  if (getsockopt(fd, SOL_SOCKET, SO_TYPE, &type, &length) != 0 || type != SOCK_DGRAM) return false;
  sockaddr_in address{};
  length = sizeof(address);
  if (getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length) != 0 || address.sin_family != AF_INET) {
    return false;
  }
  return ntohs(address.sin_port) == port;
}

}  // namespace

int UdpmReceiveSocket::PortOf(const std::string& url) {
  const std::string scheme = "udpm://";
  if (url.rfind(scheme, 0) != 0) return -1;
  const size_t end = url.find('?', scheme.size());
  const size_t length = end == std::string::npos ? std::string::npos : end - scheme.size();
  const std::string address = url.substr(scheme.size(), length);
  const size_t colon = address.find(':');
  if (colon == std::string::npos) return 7667;  // LCM's default port
  const std::string digits = address.substr(colon + 1);
  if (digits.empty() || digits.size() > 5 || digits.find_first_not_of("0123456789") != std::string::npos) return -1;
  const int port = std::stoi(digits);
  return port > 0 && port <= 65535 ? port : -1;
}

UdpmReceiveSocket::UdpmReceiveSocket(const std::string& url) : port_(PortOf(url)) {
  if (port_ < 0) return;
  for (const auto& [fd, inode] : OpenSockets()) sockets_before_.insert(inode);
}

int UdpmReceiveSocket::Find() const {
  if (port_ < 0) return -1;
  int found = -1;
  for (const auto& [fd, inode] : OpenSockets()) {
    if (sockets_before_.count(inode) != 0 || !IsUdpBoundTo(fd, port_)) continue;
    if (found >= 0) return -1;  // two candidates: not sure which is LCM's
    found = fd;
  }
  return found;
}

}  // namespace dream::lcm
