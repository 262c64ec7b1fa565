//! Why a section cannot be built.

/// A NACA designation or a user-defined section that gives no airfoil. Every variant says what
/// was found and what is accepted.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum SectionError {
    /// The designation does not have the form of its series.
    #[error(
        "NACA {series}-series designation `{designation}` cannot be read: expected {expected}"
    )]
    Form {
        series: &'static str,
        designation: String,
        expected: &'static str,
    },
    /// The designation reads, but a digit or number in it names no section of the series.
    #[error("NACA {series}-series designation `{designation}`: {what} {found} is not defined; {accepted}")]
    Undefined {
        series: &'static str,
        designation: String,
        what: &'static str,
        found: String,
        accepted: &'static str,
    },
    /// The xxSCHR coordinates of a user-defined section (TYPEIN) cannot make a section.
    #[error("user-defined section: {variable}: {problem}")]
    UserSection {
        variable: &'static str,
        problem: String,
    },
    /// A data file of `charts/sections/` is missing from the build (a packaging fault, not an
    /// input problem; the chart test catches it).
    #[error("chart {0} is not embedded in the library")]
    MissingChart(&'static str),
}
