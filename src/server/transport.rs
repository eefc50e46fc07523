//! The connections under the HTTP server. hyper answers a request it cannot read at all (a
//! malformed request line or header, a target from 64 KiB, more than 100 header fields or about
//! 400 KiB of them) by itself, before any route or middleware sees it: an empty 400, 414 or 431
//! with `connection: close`. [`JsonErrorListener`] accepts TCP connections whose writes are
//! watched for exactly that answer — a lone response head `HTTP/1.1 400|414|431`,
//! `connection: close`, `content-length: 0` — and sends it with the API's JSON error body
//! instead; every other byte passes through untouched. The server's own answers never have that
//! shape: its errors always carry a JSON body ([`super::error::json_errors`]).

use super::error::ApiError;
use axum::extract::connect_info::Connected;
use axum::http::StatusCode;
use axum::serve::{IncomingStream, Listener};
use std::io;
use std::net::SocketAddr;
use std::pin::Pin;
use std::task::{ready, Context, Poll};
use tokio::io::{AsyncRead, AsyncWrite, ReadBuf};
use tokio::net::{TcpListener, TcpStream};

/// A TCP listener whose connections answer the HTTP layer's own refusals in the JSON shape.
pub struct JsonErrorListener(pub TcpListener);

/// The client's address, as the handlers read it (`ConnectInfo<ClientAddr>`).
#[derive(Clone, Copy, Debug)]
pub struct ClientAddr(pub SocketAddr);

impl Connected<IncomingStream<'_, JsonErrorListener>> for ClientAddr {
    fn connect_info(stream: IncomingStream<'_, JsonErrorListener>) -> Self {
        ClientAddr(*stream.remote_addr())
    }
}

impl Listener for JsonErrorListener {
    type Io = JsonErrorIo;
    type Addr = SocketAddr;

    async fn accept(&mut self) -> (JsonErrorIo, SocketAddr) {
        let (io, addr) = Listener::accept(&mut self.0).await;
        (JsonErrorIo { inner: io, pending: Vec::new(), sent: 0, consumed: 0 }, addr)
    }

    fn local_addr(&self) -> io::Result<SocketAddr> {
        self.0.local_addr()
    }
}

/// One connection: reads pass through; a write that is the HTTP layer's empty refusal is sent
/// as [`json_refusal`] instead.
pub struct JsonErrorIo {
    inner: TcpStream,
    /// The replacement being written, how much of it is sent, and the length of the write it
    /// replaces (reported as written once all of it is sent).
    pending: Vec<u8>,
    sent: usize,
    consumed: usize,
}

/// The JSON form of `head` if it is the HTTP layer's own empty refusal, the whole of a write.
pub fn json_refusal(head: &[u8]) -> Option<Vec<u8>> {
    let text = std::str::from_utf8(head.strip_suffix(b"\r\n\r\n")?).ok()?;
    let mut lines = text.split("\r\n");
    let status_line = lines.next()?;
    let code: u16 = status_line.strip_prefix("HTTP/1.1 ")?.get(..3)?.parse().ok()?;
    let (api_code, message) = match code {
        400 => ("bad_request", "the request could not be read: a malformed request line or header"),
        414 => ("uri_too_long", "the request target is over 64 KiB"),
        431 => ("headers_too_large", "more than 100 header fields, or about 400 KiB of them"),
        _ => return None,
    };
    let headers: Vec<&str> = lines.collect();
    let has = |want: &str| headers.iter().any(|h| h.eq_ignore_ascii_case(want));
    if !has("content-length: 0") || !has("connection: close") {
        return None;
    }
    let body = ApiError::new(StatusCode::from_u16(code).ok()?, api_code, message).body().to_string();
    let mut out = format!("{status_line}\r\n");
    for h in headers.iter().filter(|h| !h.to_ascii_lowercase().starts_with("content-length:")) {
        out.push_str(h);
        out.push_str("\r\n");
    }
    out.push_str("content-type: application/json\r\ncache-control: no-store\r\n");
    out.push_str(&format!("content-length: {}\r\n\r\n{body}", body.len()));
    Some(out.into_bytes())
}

impl JsonErrorIo {
    /// Writes what is left of the replacement.
    fn drain(&mut self, cx: &mut Context<'_>) -> Poll<io::Result<()>> {
        while self.sent < self.pending.len() {
            let n = ready!(Pin::new(&mut self.inner).poll_write(cx, &self.pending[self.sent..]))?;
            if n == 0 {
                return Poll::Ready(Err(io::ErrorKind::WriteZero.into()));
            }
            self.sent += n;
        }
        self.pending.clear();
        self.sent = 0;
        Poll::Ready(Ok(()))
    }

    /// Starts replacing a write of `buf` if it is a refusal; then sends the replacement.
    fn poll_replaced(&mut self, cx: &mut Context<'_>, buf: Option<&[u8]>) -> Option<Poll<io::Result<usize>>> {
        if self.pending.is_empty() {
            let json = json_refusal(buf?)?;
            (self.pending, self.sent, self.consumed) = (json, 0, buf?.len());
        }
        Some(self.drain(cx).map_ok(|()| self.consumed))
    }
}

impl AsyncRead for JsonErrorIo {
    fn poll_read(self: Pin<&mut Self>, cx: &mut Context<'_>, buf: &mut ReadBuf<'_>) -> Poll<io::Result<()>> {
        Pin::new(&mut self.get_mut().inner).poll_read(cx, buf)
    }
}

impl AsyncWrite for JsonErrorIo {
    fn poll_write(self: Pin<&mut Self>, cx: &mut Context<'_>, buf: &[u8]) -> Poll<io::Result<usize>> {
        let this = self.get_mut();
        if let Some(done) = this.poll_replaced(cx, Some(buf)) {
            return done;
        }
        Pin::new(&mut this.inner).poll_write(cx, buf)
    }

    fn poll_write_vectored(
        self: Pin<&mut Self>,
        cx: &mut Context<'_>,
        bufs: &[io::IoSlice<'_>],
    ) -> Poll<io::Result<usize>> {
        let this = self.get_mut();
        // A refusal is a lone head: one non-empty slice.
        let mut full = bufs.iter().filter(|b| !b.is_empty());
        let lone = match (full.next(), full.next()) {
            (Some(only), None) => Some(&only[..]),
            _ => None,
        };
        if let Some(done) = this.poll_replaced(cx, lone) {
            return done;
        }
        Pin::new(&mut this.inner).poll_write_vectored(cx, bufs)
    }

    fn is_write_vectored(&self) -> bool {
        self.inner.is_write_vectored()
    }

    fn poll_flush(self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<io::Result<()>> {
        let this = self.get_mut();
        ready!(this.drain(cx))?;
        Pin::new(&mut this.inner).poll_flush(cx)
    }

    fn poll_shutdown(self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<io::Result<()>> {
        let this = self.get_mut();
        ready!(this.drain(cx))?;
        Pin::new(&mut this.inner).poll_shutdown(cx)
    }
}

#[cfg(test)]
mod tests {
    use super::json_refusal;

    #[test]
    fn only_the_empty_refusals_are_rewritten() {
        let head = b"HTTP/1.1 431 Request Header Fields Too Large\r\nconnection: close\r\ncontent-length: 0\r\n\
                     date: Wed, 02 Dec 2026 07:46:01 GMT\r\n\r\n";
        let out = String::from_utf8(json_refusal(head).unwrap()).unwrap();
        let (head_out, body) = out.split_once("\r\n\r\n").unwrap();
        assert!(head_out.starts_with("HTTP/1.1 431 ") && head_out.contains("date: Wed"), "{out}");
        assert!(head_out.contains(&format!("content-length: {}", body.len())), "{out}");
        let json: serde_json::Value = serde_json::from_str(body).unwrap();
        assert_eq!(json["error"]["code"], "headers_too_large");
        // Answers with a body, other statuses, or a head followed by more bytes pass through.
        assert!(json_refusal(b"HTTP/1.1 400 Bad Request\r\nconnection: close\r\ncontent-length: 12\r\n\r\n").is_none());
        assert!(json_refusal(b"HTTP/1.1 404 Not Found\r\nconnection: close\r\ncontent-length: 0\r\n\r\n").is_none());
        assert!(json_refusal(b"HTTP/1.1 400 Bad Request\r\ncontent-length: 0\r\n\r\n").is_none());
        assert!(json_refusal(b"HTTP/1.1 400 Bad Request\r\nconnection: close\r\ncontent-length: 0\r\n\r\nx").is_none());
    }
}
