#pragma once
// How hexc edit's server reads a connection: httplib's request handling, one request after another as its own loop does,
// over a stream that bounds a request's head (request line and headers) before anything sees it. Debian's cpp-httplib
// 0.11.4 is a compiled library: its caps are its own (a header line of 8 KB checked only once the line has been read
// whole, no cap on the headers' count), and it keeps every header it reads.
#include <httplib.h>

#include <chrono>
#include <cstddef>

namespace hexc::edit {

// A request's head: the page's are under 2 KB; a request line and a header at httplib's 8 KB each fit twice over.
constexpr size_t kMaxHeadBytes = 32 << 10;
// The whole head arrives within this, however slowly it trickles (each read also has the server's read timeout).
constexpr std::chrono::seconds kHeadTime{10};

class BoundedServer : public httplib::Server {
public:
    // `maxBody`: the largest body a route reads, what a connection closed before its body was read discards at most.
    explicit BoundedServer(size_t maxBody) : maxBody_(maxBody) {}

private:
    bool process_and_close_socket(socket_t sock) override;
    size_t maxBody_;
};

// Called from a handler that answers without reading the request's body: the connection is closed after this answer,
// since what follows on it is the unread body, not a request. What the client still sends of it (within the server's
// read timeout and the largest body) is read and dropped first, so that its answer is not lost to a reset.
void closeAfterAnswer();

}  // namespace hexc::edit
