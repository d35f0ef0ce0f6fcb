#include "server.h"

#include <httplib.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <random>
#include <stdexcept>
#include <thread>

#include "connection.h"
#include "hexc/suggest.h"
#include "page_files.h"

namespace hexc::edit {

namespace {

// 128 random bits as hex, from the system's entropy source, as Jupyter's token.
std::string randomToken() {
    std::random_device device;
    std::string token;
    for (int i = 0; i < 4; ++i) {
        char part[9];
        std::snprintf(part, sizeof part, "%08x", unsigned(device()));
        token += part;
    }
    return token;
}

// Compares without stopping at the first difference, so that timing tells nothing about the token.
bool sameSecret(const std::string& a, const std::string& b) {
    unsigned diff = unsigned(a.size() ^ b.size());
    for (size_t i = 0; i < a.size(); ++i) diff |= unsigned(a[i] ^ b[i % std::max<size_t>(b.size(), 1)]);
    return diff == 0;
}

void answer(httplib::Response& res, const Reply& reply) {
    res.status = reply.status;
    for (const auto& [name, value] : reply.headers) res.set_header(name, value);
    res.set_content(reply.body, reply.contentType.c_str());
}

void refuse(httplib::Response& res, int status, const std::string& why) { answer(res, {status, "hexc edit: " + why + "\n", "text/plain"}); }

const std::string& pageFile(const std::string& name) {
    static const std::string none;
    auto it = pageFiles().find(name);
    return it == pageFiles().end() ? none : it->second;
}

std::string contentType(const std::string& name) {
    if (name.ends_with(".html")) return "text/html; charset=utf-8";
    if (name.ends_with(".js")) return "text/javascript; charset=utf-8";
    if (name.ends_with(".css")) return "text/css; charset=utf-8";
    if (name.ends_with(".json")) return "application/json";
    if (name.ends_with(".svg")) return "image/svg+xml";
    return "text/plain; charset=utf-8";
}

}  // namespace

struct Server::Impl {
    Impl(Session& s, CaptureHandler c) : session(s), capture(std::move(c)) {}
    Session& session;
    CaptureHandler capture;
    BoundedServer http{kMaxRequestBytes};
    std::string token = randomToken();
    int port = 0;
    std::string url;
    std::atomic<int> streams = 0;  // change notification streams open

    std::string cookieName() const { return "hexc_edit_" + std::to_string(port); }

    // Whether the request carries the token: in the query (the printed address) or the cookie its first load set.
    bool authorised(const httplib::Request& req) const {
        if (req.has_param("token")) return sameSecret(req.get_param_value("token"), token);
        const std::string cookies = req.get_header_value("Cookie"), name = cookieName() + "=";
        for (size_t at = cookies.find(name); at != std::string::npos; at = cookies.find(name, at + 1)) {
            if (at > 0 && cookies[at - 1] != ' ' && cookies[at - 1] != ';') continue;
            const size_t begin = at + name.size(), end = std::min(cookies.find(';', begin), cookies.size());
            if (sameSecret(cookies.substr(begin, end - begin), token)) return true;
        }
        return false;
    }

    // Why a request comes from another origin than this server's page, or empty. Another page on 127.0.0.1 (another
    // port) is the same site, so the browser sends it the cookie: what the browser says of the request's origin is
    // checked. A browser sends Sec-Fetch-Site (and Origin on POST); a tool such as curl sends neither and needs the token.
    std::string crossOrigin(const httplib::Request& req) const {
        const std::string site = req.get_header_value("Sec-Fetch-Site"), origin = req.get_header_value("Origin");
        const bool navigation = req.method == "GET" && req.path == "/" && req.get_header_value("Sec-Fetch-Mode") == "navigate";
        if (!site.empty() && site != "same-origin" && !(navigation && site == "none"))
            return "a request from another site or page (Sec-Fetch-Site: " + site + "): open the address hexc edit printed";
        const std::string p = ":" + std::to_string(port);
        if (!origin.empty() && origin != "http://127.0.0.1" + p && origin != "http://localhost" + p)
            return "a request from another origin (" + origin + "): open the address hexc edit printed";
        return {};
    }

    // Refuses, before any route runs: another Host than this server's own names (a DNS rebinding page's requests carry
    // its own host name), a missing or wrong token, and a path that tries to leave the routes.
    httplib::Server::HandlerResponse guard(const httplib::Request& req, httplib::Response& res) const {
        const std::string host = req.get_header_value("Host"), p = ":" + std::to_string(port);
        if (host != "127.0.0.1" + p && host != "localhost" + p) {
            refuse(res, 403, "wrong Host header `" + host + "`: open 127.0.0.1" + p + " or localhost" + p);
            return httplib::Server::HandlerResponse::Handled;
        }
        if (!authorised(req)) {
            refuse(res, 403, "missing or wrong token: open the address hexc edit printed");
            return httplib::Server::HandlerResponse::Handled;
        }
        if (const std::string why = crossOrigin(req); !why.empty()) {
            refuse(res, 403, why);
            return httplib::Server::HandlerResponse::Handled;
        }
        // This runs before the body is read: a body that would be inflated or read in chunks without a stated length
        // (the page never sends one) is refused before it costs memory.
        if (req.has_header("Transfer-Encoding") ||
            (req.has_header("Content-Encoding") && req.get_header_value("Content-Encoding") != "identity")) {
            refuse(res, 415, "compressed or chunked request bodies are refused: send the body as it is, with its length");
            return httplib::Server::HandlerResponse::Handled;
        }
        if (const std::string why = overBodyLimit(req); !why.empty()) {
            refuse(res, why.starts_with("no ") ? 411 : 413, why);
            return httplib::Server::HandlerResponse::Handled;
        }
        const std::string target = lowerCase(req.target);
        for (const char* bad : {"..", "%2e", "%2f", "%5c", "\\", "//"})
            if (target.find(bad) != std::string::npos || req.path.find(bad) != std::string::npos) {
                refuse(res, 403, "path refused: hexc edit serves its page, the material and its textures only");
                return httplib::Server::HandlerResponse::Handled;
            }
        return httplib::Server::HandlerResponse::Unhandled;
    }

    // The most a route reads of a request's body: a material's size for the routes that take one, a frame's for a
    // capture, none for the rest.
    size_t bodyLimit(const httplib::Request& req) const {
        if (req.method != "POST") return 0;
        if (req.path == "/api/compile" || req.path == "/api/cost" || req.path == "/api/save") return kMaxDocumentBytes;
        return req.path == "/api/capture" && capture ? kMaxRequestBytes : 0;
    }

    // Why a request's body is refused from its stated length, before a byte of it is read, or empty. httplib reads a body
    // whose length is not stated until the connection closes, whatever the route.
    std::string overBodyLimit(const httplib::Request& req) const {
        const std::string length = req.get_header_value("Content-Length");
        const bool bodiless = req.method == "GET" || req.method == "HEAD" || req.method == "OPTIONS";
        if (length.empty()) return bodiless ? "" : "no Content-Length: send the body with its length";
        const size_t limit = bodyLimit(req);
        if (length.size() > 12 || length.find_first_not_of("0123456789") != std::string::npos || std::stoull(length) > limit)
            return "request too large: " + req.method + " " + req.path + " takes at most " + std::to_string(limit) + " bytes";
        return {};
    }

    void routes();
    void events(httplib::Response& res);
    void bodyRoute(const std::string& path, std::function<Reply(const std::string&)> handle);
};

void Server::Impl::bodyRoute(const std::string& path, std::function<Reply(const std::string&)> handle) {
    http.Post(path, [handle](const httplib::Request& req, httplib::Response& res) { answer(res, handle(req.body)); });
}

namespace {

// What escapes a route is a hexc bug: the page gets it as an internal diagnostic, and the server goes on.
void internalError(const httplib::Request& req, httplib::Response& res, std::exception_ptr error) {
    std::string what = "unknown exception";
    try {
        std::rethrow_exception(error);
    } catch (const std::exception& e) {
        what = e.what();
    } catch (...) {
    }
    const Diagnostic d = Diagnostic::make(Code::Internal, {req.path}, "", "hexc edit failed: " + what);
    answer(
        res,
        {500, nlohmann::json({{"ok", false}, {"diagnostics", {{{"text", d.format()}, {"code", std::string(toString(d.code))}}}}}).dump()});
}

}  // namespace

// Server-sent events: `data: VERSION` at once and whenever the material file or a texture changes (Session::version,
// which only stats files unless the material changed). At most kEventStreams at once (503 beyond: the page falls back to
// asking), each ends after kEventStreamLife; the page's EventSource reconnects after the `retry` it is given. A stream
// ends when its client goes (seen at its next look, kEventLook, as a closed connection) or the server stops (httplib
// stops calling the provider), and its slot with it.
void Server::Impl::events(httplib::Response& res) {
    if (++streams > kEventStreams) {
        --streams;
        return refuse(res, 503, "too many change notification streams open");
    }
    const auto end = std::chrono::steady_clock::now() + kEventStreamLife;
    auto sent = std::make_shared<std::string>();
    res.set_chunked_content_provider(
        "text/event-stream",
        [this, end, sent](size_t, httplib::DataSink& sink) {
            if (!sink.is_writable()) return false;
            if (const std::string v = session.version(); v != *sent) {
                *sent = v;
                const std::string event = "retry: 200\ndata: " + v + "\n\n";
                if (!sink.write(event.data(), event.size())) return false;
            }
            if (std::chrono::steady_clock::now() >= end) {
                sink.done();
                return true;
            }
            std::this_thread::sleep_for(kEventLook);
            return true;
        },
        [this](bool) { --streams; });
}

void Server::Impl::routes() {
    http.Get("/", [this](const httplib::Request& req, httplib::Response& res) {
        // The token in the address becomes a cookie, so that the page's own requests carry it.
        if (req.has_param("token")) res.set_header("Set-Cookie", cookieName() + "=" + token + "; HttpOnly; SameSite=Strict; Path=/");
        answer(res, {200, pageFile("index.html"), contentType("index.html")});
    });
    // The icon browsers ask for by this name whatever the page says: the page's own, so that no request is a 404.
    http.Get("/favicon.ico", [](const httplib::Request&, httplib::Response& res) {
        answer(res, {200, pageFile("favicon.svg"), contentType("favicon.svg")});
    });
    http.Get(R"(/([a-z]+\.(js|css|svg)))", [](const httplib::Request& req, httplib::Response& res) {
        const std::string name = req.matches[1];
        if (pageFile(name).empty()) return refuse(res, 404, "no such file: " + name);
        answer(res, {200, pageFile(name), contentType(name)});
    });
    http.Get("/api/schema", [](const httplib::Request&, httplib::Response& res) {
        answer(res, {200, pageFile("material.schema.json"), "application/json"});
    });
    http.Get(R"(/api/shader/([a-z]+\.(vert|frag)\.glsl))", [](const httplib::Request& req, httplib::Response& res) {
        const std::string name = req.matches[1];
        if (pageFile(name).empty()) return refuse(res, 404, "no such shader: " + name);
        answer(res, {200, pageFile(name), "text/plain; charset=utf-8"});
    });
    http.Get("/api/material", [this](const httplib::Request&, httplib::Response& res) { answer(res, session.material()); });
    http.Get("/api/version", [this](const httplib::Request&, httplib::Response& res) {
        answer(res, {200, nlohmann::json({{"version", session.version()}}).dump()});
    });
    http.Get("/api/events", [this](const httplib::Request&, httplib::Response& res) { events(res); });
    http.Get(R"(/api/texture/([a-z][a-z0-9_]*(\.lut|\.gaussian)?))",
             [this](const httplib::Request& req, httplib::Response& res) { answer(res, session.texture(req.matches[1])); });
    bodyRoute("/api/compile", [this](const std::string& body) { return session.compile(body); });
    bodyRoute("/api/cost", [this](const std::string& body) { return session.cost(body); });
    bodyRoute("/api/save", [this](const std::string& body) { return session.save(body); });
    if (!capture) return;
    http.Post("/api/capture", [this](const httplib::Request& req, httplib::Response& res) {
        const int width = std::atoi(req.get_header_value("X-Hexc-Width").c_str());
        const int height = std::atoi(req.get_header_value("X-Hexc-Height").c_str());
        answer(res, capture(width, height, req.body, req.has_header("X-Hexc-Error")));
    });
}

Server::Server(Session& session, int port, CaptureHandler capture) : impl_(std::make_unique<Impl>(session, std::move(capture))) {
    Impl& s = *impl_;
    s.http.set_payload_max_length(kMaxRequestBytes);
    // A client that opens a connection and sends slowly holds a worker until a read times out: more workers than a page
    // uses (it sends a few requests at once), and short timeouts, so that a few such clients block nothing; a request's
    // head is bounded in size and time (connection.h), its body by its route before it is read (guard()).
    s.http.new_task_queue = [] { return new httplib::ThreadPool(kWorkers); };
    s.http.set_read_timeout(2);
    s.http.set_write_timeout(5);
    s.http.set_keep_alive_timeout(2);
    s.http.set_default_headers({{"Cache-Control", "no-store"},
                                {"X-Content-Type-Options", "nosniff"},
                                {"Referrer-Policy", "no-referrer"},  // the address holds the token
                                {"Content-Security-Policy", "default-src 'self'; img-src 'self' blob: data:; frame-ancestors 'none'"}});
    s.http.set_exception_handler(internalError);
    s.http.set_pre_routing_handler([&s](const httplib::Request& req, httplib::Response& res) {
        // Every answer goes out as it is. For a browser that accepts Brotli (Chromium does) httplib compresses whatever
        // it counts as text at Brotli's default quality, 11: 0.2-0.3 s of a structural edit's 70 KB answer on a loaded
        // machine, where sending it over the loopback takes a millisecond. httplib has no switch for it; it reads the
        // request's Accept-Encoding when it writes the answer, and the request is its own non-const object (only the
        // handler sees it const).
        const_cast<httplib::Request&>(req).headers.erase("Accept-Encoding");
        const httplib::Server::HandlerResponse handled = s.guard(req, res);
        if (handled == httplib::Server::HandlerResponse::Handled) closeAfterAnswer();  // its body, if any, is left unread
        return handled;
    });
    s.port = port == 0 ? s.http.bind_to_any_port("127.0.0.1") : (s.http.bind_to_port("127.0.0.1", port) ? port : -1);
    if (s.port <= 0) throw std::runtime_error("cannot listen on 127.0.0.1:" + std::to_string(port) + " (in use?)");
    s.url = "http://127.0.0.1:" + std::to_string(s.port) + "/?token=" + s.token;
    s.routes();
}

Server::~Server() = default;
int Server::port() const { return impl_->port; }
const std::string& Server::url() const { return impl_->url; }
void Server::run() { impl_->http.listen_after_bind(); }
void Server::stop() { impl_->http.stop(); }

}  // namespace hexc::edit
