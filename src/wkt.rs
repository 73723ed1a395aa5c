//! (being written)
pub fn parse_wkt(_text: &str, file: &str) -> crate::Result<crate::Region> {
    Err(crate::Error::parse(file, 1, 1, "WKT not yet supported"))
}
