//! esmini's UDP framing and the OSI trace-file format: a message longer than 8,192 bytes goes
//! as parts numbered 1, 2, … with the last negated, each with its length, and the receiver's
//! concatenation is the message; a trace file is the messages each after its 4-byte
//! little-endian length, read back whole, a cut-off one refused; an unfinished writer leaves no
//! file.

use std::net::UdpSocket;
use std::time::Duration;

use crate::common::*;

#[test]
fn long_messages_go_in_numbered_parts_as_esmini_sends_them() {
    let message: Vec<u8> = (0..20_000u32).map(|i| (i % 251) as u8).collect();
    let receiver = UdpSocket::bind("127.0.0.1:0").expect("socket");
    receiver.set_read_timeout(Some(Duration::from_secs(5))).expect("timeout");
    let mut sender = osi::Sender::new(receiver.local_addr().expect("address")).expect("sender");
    sender.send(&message);
    sender.send(&[7u8; 10]);
    let mut parts = Vec::new();
    let mut buf = [0u8; 8208];
    for _ in 0..4 {
        let n = receiver.recv(&mut buf).expect("a datagram");
        let counter = i32::from_le_bytes(buf[0..4].try_into().expect("4 bytes"));
        let size = u32::from_le_bytes(buf[4..8].try_into().expect("4 bytes")) as usize;
        assert_eq!(size, n - 8, "the length is the part's");
        parts.push((counter, buf[8..n].to_vec()));
    }
    assert_eq!(parts.iter().map(|p| (p.0, p.1.len())).collect::<Vec<_>>(), [(1, 8192), (2, 8192), (-3, 3616), (-1, 10)]);
    assert_eq!(parts[..3].iter().flat_map(|p| p.1.clone()).collect::<Vec<_>>(), message);
    assert_eq!(sender.failed, 0);
    assert_eq!(osi::receiver_address("127.0.0.1").expect("address").port(), 48198);
    assert_eq!(osi::receiver_address("localhost:5000").expect("address").port(), 5000);
}

#[test]
fn trace_files_hold_each_message_after_its_length() {
    let dir = work_dir("framing");
    let path = dir.join("t.osi");
    let messages = vec![vec![1u8, 2, 3], Vec::new(), vec![9u8; 300]];
    osi::trace_file::write(&path, &messages).expect("written");
    let bytes = std::fs::read(&path).expect("read");
    assert_eq!(&bytes[..7], &[3, 0, 0, 0, 1, 2, 3]);
    assert_eq!(osi::trace_file::read(&bytes).expect("whole"), messages.iter().map(Vec::as_slice).collect::<Vec<_>>());
    assert!(osi::trace_file::read(&bytes[..bytes.len() - 1]).is_err(), "a cut-off message is refused");
    let unfinished = dir.join("u.osi");
    let mut w = osi::TraceWriter::create(&unfinished).expect("created");
    w.write(&[1, 2]).expect("written");
    drop(w);
    assert!(
        std::fs::read_dir(&dir).expect("dir").flatten().all(|e| e.file_name() != "u.osi" && !e.file_name().to_string_lossy().contains(".tmp")),
        "no file left"
    );
}

/// A trace written to a pipe (or `/dev/null`) goes through it, and the pipe stays a pipe.
#[test]
fn a_trace_file_that_is_a_pipe_is_written_in_place() {
    let dir = work_dir("framing-fifo");
    let path = dir.join("t.osi");
    let _ = std::fs::remove_file(&path);
    let Some(fifo) = testkit::Fifo::new(&path) else { return };
    osi::trace_file::write(&path, &[vec![7u8, 8]]).expect("written");
    assert_eq!(fifo.received(), [2, 0, 0, 0, 7, 8]);
}
