//! Out-of-order detection by frame number, per object: a message whose frame is older than the
//! newest accepted one is stale (UDP may reorder datagrams) and turned away. A frame equal to
//! the newest passes: esmini's own minimalistic client sends frame 0 every time.

use crate::rejection::Reason;

/// The newest frame accepted for one object.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct FrameOrder {
    newest: Option<u32>,
}

impl FrameOrder {
    /// Accepts `frame` unless it is older than the newest accepted, which it then becomes.
    pub fn admit(&mut self, frame: u32) -> Result<(), Reason> {
        match self.newest {
            Some(newest) if frame < newest => Err(Reason::OutOfOrder { frame, newest }),
            _ => {
                self.newest = Some(frame);
                Ok(())
            }
        }
    }

    /// The newest frame accepted so far.
    pub fn newest(&self) -> Option<u32> {
        self.newest
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn older_frames_are_stale_equal_ones_pass() {
        let mut order = FrameOrder::default();
        assert_eq!(order.admit(5), Ok(()));
        assert_eq!(order.admit(5), Ok(()));
        assert_eq!(order.admit(4), Err(Reason::OutOfOrder { frame: 4, newest: 5 }));
        // a rejected frame does not move the mark
        assert_eq!(order.newest(), Some(5));
        assert_eq!(order.admit(9), Ok(()));
        assert_eq!(order.admit(6), Err(Reason::OutOfOrder { frame: 6, newest: 9 }));
    }
}
