//! opendrive
