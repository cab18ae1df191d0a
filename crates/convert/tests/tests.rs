//! The conversion pipeline's tests, one binary whose modules are its features: the trace's way
//! to CommonRoad (`trace_to_commonroad`, `table_i`, `add_delete_entity`, `trailers_corpus`,
//! `light_cycles`), `trace_audit`, `header_and_summary`, `report_files` (the batch's report files) and `closed_loop` (sessions
//! against the batch). `common` builds the synthetic traces and scenarios.

mod common;

mod add_delete_entity;
mod closed_loop;
mod header_and_summary;
mod light_cycles;
mod report_files;
mod table_i;
mod trace_audit;
mod trace_to_commonroad;
mod trailers_corpus;
