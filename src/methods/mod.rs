//! DATCOM methods, one module per section family of the handbook. Each method is a pure
//! function over geometry and flight conditions that returns its named terms and warnings.
//!
//! The methods take their input as given: they do not check a case for values that are not
//! numbers (NaN or ±inf, which no deck can give), and such a value gives terms that are not
//! numbers either. [`crate::results::run_case`] checks the case first and computes it without
//! them, with a warning; before calling a method directly on a case built in code, check it
//! with [`crate::Case::values_not_numbers`] (or [`crate::Case::diagnose`], which also gives
//! the deck's checks).
//!
//! Nor do they check the schedule or the conditions they are given: the angles of attack
//! `alpha_deg` must be strictly increasing (as `run_case` sorts them), and the case's
//! `conditions` must be those of its flight input ([`crate::Case::prepare`] after editing it;
//! `run_case` warns when they are not). Their values at an angle depend on the other angles of
//! the schedule, as the original's do (docs/tail.md).

pub mod body;
pub mod dynamic;
pub mod experimental;
pub mod lateral;
pub mod low_aspect_ratio;
pub mod section;
pub mod tail;
pub mod wing;
pub mod wing_body;
