//! DATCOM methods, one module per section family of the handbook. Each method is a pure
//! function over geometry and flight conditions that returns its named terms and warnings.

pub mod body;
pub mod dynamic;
pub mod experimental;
pub mod lateral;
pub mod low_aspect_ratio;
pub mod section;
pub mod tail;
pub mod wing;
pub mod wing_body;
