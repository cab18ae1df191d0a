//! CommonRoad 2020a XML: written against the XSD, read back, checked by `cr_check.py`.

mod atomic_write;
mod cr_check_oracle;
mod escaping;
mod number_format;
mod read_2018b;
mod read_back;
mod structure;
