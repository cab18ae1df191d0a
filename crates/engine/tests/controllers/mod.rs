//! The driver models (controllers), each against hand computations or esmini 3.6.0's runs.

mod acc;
mod alks;
mod alks_r157;
mod follow_route;
mod looming;
mod natural_driver;
