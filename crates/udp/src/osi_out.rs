//! The OSI side of a served run: after every frame (the Init frame once its ports were read,
//! as esmini reports after its controllers stepped) the GroundTruth message of the frame is
//! composed (`osi::Reporter`), sent to the OSI receiver in esmini's framing if one was named, and
//! handed to the observer (which may write the trace file). A client written for esmini reads
//! the message of frame k, answers, and its answer drives frame k + 1, as with esmini.

use std::net::SocketAddr;

use convert::ClosedLoop;
use osi::{Reporter, Sender};

use crate::observer::Observer;

/// Composes and sends the messages of one run.
pub struct OsiOut {
    reporter: Reporter,
    sender: Option<Sender>,
    pub frames: usize,
}

impl OsiOut {
    /// The OSI output of `session`'s run, sending to `receiver` if given.
    pub fn new(session: &ClosedLoop, receiver: Option<SocketAddr>) -> std::io::Result<OsiOut> {
        let reporter = Reporter::new(session.scenario(), session.road(), &session.entity_names());
        let sender = receiver.map(Sender::new).transpose()?;
        Ok(OsiOut { reporter, sender, frames: 0 })
    }

    /// The frame `session` is at: composed, sent, and told to `observer`.
    pub fn frame(&mut self, session: &ClosedLoop, observer: &mut dyn Observer) {
        let states: Vec<_> = (0..session.entity_names().len()).map(|i| session.state(i)).collect();
        let message = self.reporter.encoded_frame(session.road(), session.time(), &states);
        if let Some(s) = &mut self.sender {
            s.send(&message);
        }
        self.frames += 1;
        observer.osi_frame(&message);
    }

    /// What could not be reported as esmini reports it, and datagrams the network refused.
    pub fn notes(&self) -> Vec<String> {
        let mut notes: Vec<String> = self.reporter.warnings().to_vec();
        if let Some(s) = self.sender.as_ref().filter(|s| s.failed > 0) {
            notes.push(format!("OSI: {} messages could not be sent whole to {}", s.failed, s.receiver));
        }
        notes
    }
}
