//! Airfoil sections: coordinates from NACA designations or from the xxSCHR namelists, and the
//! section characteristics the original prints on its SECTION DEFINITION pages.
