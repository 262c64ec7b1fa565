//! Derived geometry: planforms, bodies and airfoil sections, as the DATCOM methods need them.

pub mod section;
