// Connects to 127.0.0.1 half a second into the run.
#include "misbehave.hpp"
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
Behavior<Wheels> opensSocket(const Robot&) {
  return misbehaveFrom(0.5, [] {
    const int s = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in to{};
    to.sin_family = AF_INET;
    to.sin_port = htons(9);
    to.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    ::connect(s, reinterpret_cast<sockaddr*>(&to), sizeof to);
  });
}
FROB_CONTROLLER(opensSocket)
