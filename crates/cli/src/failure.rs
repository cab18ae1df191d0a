//! How a command fails: the message the user reads and the exit status (0 success, 1 some
//! files of a batch failed, 2 bad usage or bad input). Every command returns it; `main` prints
//! it and exits with its status.

/// A failed command: the message for the user and the exit status.
pub(crate) struct Failure {
    pub(crate) message: String,
    pub(crate) status: u8,
}

impl Failure {
    /// Bad input or usage (exit status 2).
    pub(crate) fn input(message: impl Into<String>) -> Self {
        Failure { message: message.into(), status: 2 }
    }
}
