//! Derived geometry: planforms, bodies and airfoil sections, as the DATCOM methods need them.

pub mod airfoil_file;
pub mod body;
pub mod planform;
pub mod section;

pub use body::{body, BodyError, BodyGeometry};
pub use planform::{planform, GeometryError, Panel, PlanformGeometry, Span};
