//! Lexemes of namelist text, recognised with nom, one physical line at a time.
//!
//! The grammar above lexemes (assignments, value lists, recovery) is in `namelist.rs`: it needs
//! look-ahead across lines and error recovery, which is clearer written over tokens. Tokens
//! borrow their text from the line: reading a deck copies no names or numbers.
//!
//! The recognisers work on the line's bytes: every lexeme but `Other` is ASCII, so a byte is a
//! character there, and byte predicates spare the UTF-8 decoding of `char` input.

use std::borrow::Cow;

use nom::branch::alt;
use nom::bytes::complete::{tag_no_case, take_while1};
use nom::character::complete::{char, digit0, digit1, satisfy};
use nom::combinator::{opt, verify};
use nom::sequence::{pair, preceded, tuple};
use nom::IResult;

/// A lexeme of namelist text.
#[derive(Debug, Clone, PartialEq)]
pub enum Tok<'a> {
    /// A name: variable, or the T/F logical constants (decided by the parser). Upper case.
    Name(Cow<'a, str>),
    /// `$NAME`: opens a namelist. Upper case.
    Open(Cow<'a, str>),
    /// `$` or `&END`/`$END`: closes a namelist.
    Close,
    LParen,
    RParen,
    Equals,
    Comma,
    Star,
    /// A number; `integer` when written without `.` or exponent.
    Number {
        value: f64,
        integer: bool,
        text: &'a str,
    },
    Logical(bool),
    /// Anything else, one character.
    Other(char),
}

impl Tok<'_> {
    /// The token as written (upper case).
    pub fn text(&self) -> String {
        match self {
            Tok::Name(n) => n.to_string(),
            Tok::Open(n) => format!("${n}"),
            Tok::Close => "$".into(),
            Tok::LParen => "(".into(),
            Tok::RParen => ")".into(),
            Tok::Equals => "=".into(),
            Tok::Comma => ",".into(),
            Tok::Star => "*".into(),
            Tok::Number { text, .. } => text.to_string(),
            Tok::Logical(b) => (if *b { ".TRUE." } else { ".FALSE." }).into(),
            Tok::Other(c) => c.escape_default().to_string(),
        }
    }

    /// How the token reads in a message.
    pub fn describe(&self) -> String {
        match self {
            Tok::Name(n) => format!("`{n}`"),
            Tok::Open(n) => format!("`${n}`"),
            Tok::Close => "`$`".into(),
            Tok::LParen => "`(`".into(),
            Tok::RParen => "`)`".into(),
            Tok::Equals => "`=`".into(),
            Tok::Comma => "`,`".into(),
            Tok::Star => "`*`".into(),
            Tok::Number { text, .. } => format!("`{text}`"),
            Tok::Logical(b) => format!("`{}`", if *b { ".TRUE." } else { ".FALSE." }),
            Tok::Other(c) => format!("`{c}`"),
        }
    }
}

/// A token with its 1-based line and column.
#[derive(Debug, Clone, PartialEq)]
pub struct Token<'a> {
    pub tok: Tok<'a>,
    pub line: usize,
    pub column: usize,
}

/// `s` in upper case, copied only when it has lower-case letters.
pub fn upper(s: &str) -> Cow<'_, str> {
    if s.bytes().any(|b| b.is_ascii_lowercase()) {
        Cow::Owned(s.to_ascii_uppercase())
    } else {
        Cow::Borrowed(s)
    }
}

fn is_name_char(c: u8) -> bool {
    c.is_ascii_alphanumeric() || c == b'_'
}

/// A name: a letter, then letters, digits and `_`.
fn name(i: &[u8]) -> IResult<&[u8], &[u8]> {
    verify(take_while1(is_name_char), |n: &[u8]| {
        n[0].is_ascii_alphabetic()
    })(i)
}

/// `$NAME`, `$END` or a bare `$` (and the same with `&`); the name's length in bytes.
fn open_or_close(i: &[u8]) -> IResult<&[u8], Option<usize>> {
    let (rest, _) = satisfy(|c| matches!(c, '$' | '&'))(i)?;
    match name(rest) {
        Ok((after, n)) if n.eq_ignore_ascii_case(b"END") => Ok((after, None)),
        Ok((after, n)) => Ok((after, Some(n.len()))),
        Err(_) => Ok((rest, None)),
    }
}

/// `.TRUE.`, `.FALSE.`, `.T.` or `.F.`, any case.
fn logical(i: &[u8]) -> IResult<&[u8], bool> {
    let (rest, word) = alt((
        tag_no_case(".TRUE."),
        tag_no_case(".FALSE."),
        tag_no_case(".T."),
        tag_no_case(".F."),
    ))(i)?;
    Ok((rest, word[1].eq_ignore_ascii_case(&b'T')))
}

/// The parts of a number as written: digits before and after the point, and the exponent.
struct Numeral<'a> {
    negative: bool,
    whole: &'a [u8],
    /// The digits after `.`; `None` without a point.
    fraction: Option<&'a [u8]>,
    exponent: Option<Exponent<'a>>,
}

struct Exponent<'a> {
    /// A Fortran `D` (double precision) exponent rather than `E`.
    fortran: bool,
    negative: bool,
    digits: &'a [u8],
}

fn sign(i: &[u8]) -> IResult<&[u8], bool> {
    let (rest, s) = opt(satisfy(|c| matches!(c, '+' | '-')))(i)?;
    Ok((rest, s == Some('-')))
}

fn exponent(i: &[u8]) -> IResult<&[u8], Exponent<'_>> {
    let (rest, (letter, negative, digits)) = tuple((
        satisfy(|c| matches!(c, 'e' | 'E' | 'd' | 'D')),
        sign,
        digit1,
    ))(i)?;
    let fortran = matches!(letter, 'd' | 'D');
    Ok((
        rest,
        Exponent {
            fortran,
            negative,
            digits,
        },
    ))
}

/// The digits before the point, and after it (`None` without a point).
type Mantissa<'a> = (&'a [u8], Option<&'a [u8]>);

/// `.` and a fraction, with no digits before the point.
fn fraction_only(i: &[u8]) -> IResult<&[u8], Mantissa<'_>> {
    let (rest, fraction) = preceded(char('.'), digit1)(i)?;
    Ok((rest, (&i[..0], Some(fraction))))
}

/// Digits with an optional `.` and fraction, or `.` and a fraction.
fn mantissa(i: &[u8]) -> IResult<&[u8], Mantissa<'_>> {
    alt((
        pair(digit1, opt(preceded(char('.'), digit0))),
        fraction_only,
    ))(i)
}

/// A number: optional sign, digits with an optional `.` and fraction (or `.` and a fraction),
/// optional exponent `E`/`D` with optional sign and digits.
fn numeral(i: &[u8]) -> IResult<&[u8], Numeral<'_>> {
    let (rest, (negative, (whole, fraction), exponent)) =
        tuple((sign, mantissa, opt(exponent)))(i)?;
    Ok((
        rest,
        Numeral {
            negative,
            whole,
            fraction,
            exponent,
        },
    ))
}

/// Powers of ten that `f64` holds exactly.
const EXACT_POWERS_OF_TEN: [f64; 23] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16,
    1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
];

impl Numeral<'_> {
    /// The value when it is one exactly rounded operation on exact operands (Clinger's fast
    /// path: at most 2^53 in the digits, a power of ten up to 1e22), which is then the
    /// correctly rounded value `str::parse` gives too; `None` otherwise. Deck numbers are short
    /// decimals: nearly all take this path.
    fn exact_value(&self) -> Option<f64> {
        let fraction = self.fraction.unwrap_or_default();
        // Up to 19 digits fit in a u64 (longer numerals are left to `str::parse`).
        if self.whole.len() + fraction.len() > 19 {
            return None;
        }
        let digits = self
            .whole
            .iter()
            .chain(fraction)
            .fold(0u64, |n, d| n * 10 + u64::from(d - b'0'));
        if digits > 1 << 53 {
            return None;
        }
        let mut power = -i64::try_from(fraction.len()).ok()?;
        if let Some(e) = &self.exponent {
            if e.digits.len() > 4 {
                return None;
            }
            let n = e
                .digits
                .iter()
                .fold(0i64, |n, &d| n * 10 + i64::from(d - b'0'));
            power += if e.negative { -n } else { n };
        }
        let magnitude = if digits == 0 {
            0.0
        } else {
            let scale = EXACT_POWERS_OF_TEN.get(usize::try_from(power.unsigned_abs()).ok()?)?;
            if power < 0 {
                digits as f64 / scale
            } else {
                digits as f64 * scale
            }
        };
        Some(if self.negative { -magnitude } else { magnitude })
    }
}

/// A number token of `text`, which `numeral` recognised in full.
fn number_token<'a>(text: &'a str, n: &Numeral) -> Tok<'a> {
    let integer = n.exponent.is_none() && n.fraction.is_none();
    // A number beyond the f64 range becomes infinite and the parser reports it. `str::parse`
    // reads what `numeral` accepts once a Fortran `D` exponent reads `E`.
    let value = n.exact_value().unwrap_or_else(|| {
        let parsed = match &n.exponent {
            Some(e) if e.fortran => text.replace(['d', 'D'], "E").parse::<f64>(),
            _ => text.parse::<f64>(),
        };
        parsed.unwrap_or(f64::INFINITY)
    });
    Tok::Number {
        value,
        integer,
        text,
    }
}

fn punct(i: &[u8]) -> IResult<&[u8], Tok<'static>> {
    let (rest, c) = satisfy(|c| matches!(c, '(' | ')' | ',' | '=' | '*'))(i)?;
    let t = match c {
        '(' => Tok::LParen,
        ')' => Tok::RParen,
        ',' => Tok::Comma,
        '=' => Tok::Equals,
        _ => Tok::Star,
    };
    Ok((rest, t))
}

/// One lexeme and its length in bytes. The first character decides which lexemes can start
/// here (the same choice as trying open/close, logical, number, punctuation and name in turn,
/// without the failed tries); anything that starts none is one character of `Other`.
fn token(i: &str) -> (usize, Tok<'_>) {
    let b = i.as_bytes();
    let rest_len = |rest: &[u8]| b.len() - rest.len();
    let found = match b[0] {
        b'$' | b'&' => open_or_close(b).map(|(rest, name)| {
            let len = rest_len(rest);
            let tok = match name {
                Some(n) => Tok::Open(upper(&i[len - n..len])),
                None => Tok::Close,
            };
            (len, tok)
        }),
        b'.' => match logical(b) {
            Ok((rest, value)) => Ok((rest_len(rest), Tok::Logical(value))),
            Err(_) => numeral(b).map(|(rest, n)| {
                let len = rest_len(rest);
                (len, number_token(&i[..len], &n))
            }),
        },
        b'0'..=b'9' | b'+' | b'-' => numeral(b).map(|(rest, n)| {
            let len = rest_len(rest);
            (len, number_token(&i[..len], &n))
        }),
        b'(' | b')' | b',' | b'=' | b'*' => punct(b).map(|(rest, t)| (rest_len(rest), t)),
        _ => name(b).map(|(rest, _)| {
            let len = rest_len(rest);
            (len, Tok::Name(upper(&i[..len])))
        }),
    };
    found.unwrap_or_else(|_: nom::Err<nom::error::Error<&[u8]>>| {
        let c = i.chars().next().unwrap_or_default();
        (c.len_utf8(), Tok::Other(c))
    })
}

/// Splits one line of namelist text (already stripped of a trailing `!` comment) into tokens.
/// `first_column` is the 1-based column of the first character of `text`.
pub fn lex_line<'a>(text: &'a str, line: usize, first_column: usize, out: &mut Vec<Token<'a>>) {
    let mut at = 0;
    let mut column = first_column;
    while let Some(c) = text.as_bytes().get(at) {
        if matches!(c, b' ' | b'\t') {
            at += 1;
            column += 1;
            continue;
        }
        let (len, tok) = token(&text[at..]);
        // Every lexeme but `Other` is ASCII: one column a byte.
        let width = if matches!(tok, Tok::Other(_)) { 1 } else { len };
        out.push(Token { tok, line, column });
        column += width;
        at += len;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn toks(s: &str) -> Vec<Tok<'_>> {
        let mut v = Vec::new();
        lex_line(s, 1, 1, &mut v);
        v.into_iter().map(|t| t.tok).collect()
    }

    #[test]
    fn numbers_in_every_spelling() {
        let expect = [
            ("1", 1.0, true),
            ("-2.", -2.0, false),
            (".5", 0.5, false),
            ("1.07E6", 1.07e6, false),
            ("0.25E-3", 0.25e-3, false),
            ("1E6", 1e6, false),
            ("+3.0D2", 300.0, false),
        ];
        for (s, v, int) in expect {
            match &toks(s)[..] {
                [Tok::Number { value, integer, .. }] => {
                    assert_eq!(*value, v, "{s}");
                    assert_eq!(*integer, int, "{s}");
                }
                other => panic!("{s}: {other:?}"),
            }
        }
    }

    #[test]
    fn values_are_what_str_parse_reads() {
        let mut spellings: Vec<String> = [
            "0",
            "-0",
            "-0.0",
            "0.1",
            "0.3",
            "1.07E6",
            "0.0588",
            "1E22",
            "1E23",
            "9007199254740993",
            "9007199254740992",
            "123456789012345678",
            ".1E-22",
            "1E-23",
            "17.0D-3",
            "4.9E-324",
            "1.8E308",
            "2E308",
            "0E999",
            "00000000000000000000001.5",
            "3.14159265358979323846",
            "1.000000000000000000",
            "-6.0",
            "+.5",
            "12345.6789E-10",
        ]
        .map(String::from)
        .to_vec();
        for i in 0..2000u32 {
            let mantissa = i.wrapping_mul(2_654_435_761) % 100_000;
            let point = i % 7;
            let exp = i % 61;
            let digits = mantissa.to_string();
            let (a, b) = digits.split_at((point as usize).min(digits.len()));
            spellings.push(format!("{a}.{b}E{}", exp as i32 - 30));
            spellings.push(format!("-{a}.{b}"));
        }
        for s in &spellings {
            let expect = s.replace('D', "E").parse::<f64>().unwrap();
            match &toks(s)[..] {
                [Tok::Number { value, .. }] => {
                    assert_eq!(value.to_bits(), expect.to_bits(), "{s}");
                }
                other => panic!("{s}: {other:?}"),
            }
        }
    }

    #[test]
    fn assignment_with_repeat_and_logical() {
        assert_eq!(
            toks(" $VTSCHR CLALPA(1)=2*0.141, VERTUP=.TRUE.$"),
            vec![
                Tok::Open("VTSCHR".into()),
                Tok::Name("CLALPA".into()),
                Tok::LParen,
                Tok::Number {
                    value: 1.0,
                    integer: true,
                    text: "1"
                },
                Tok::RParen,
                Tok::Equals,
                Tok::Number {
                    value: 2.0,
                    integer: true,
                    text: "2"
                },
                Tok::Star,
                Tok::Number {
                    value: 0.141,
                    integer: false,
                    text: "0.141"
                },
                Tok::Comma,
                Tok::Name("VERTUP".into()),
                Tok::Equals,
                Tok::Logical(true),
                Tok::Close,
            ]
        );
    }

    #[test]
    fn columns_count_characters() {
        let mut v = Vec::new();
        lex_line("\tA = 1", 7, 1, &mut v);
        let cols: Vec<usize> = v.iter().map(|t| t.column).collect();
        assert_eq!(cols, vec![2, 4, 6]);
    }

    #[test]
    fn garbage_is_one_character_at_a_time() {
        assert_eq!(
            toks("@1"),
            vec![
                Tok::Other('@'),
                Tok::Number {
                    value: 1.0,
                    integer: true,
                    text: "1"
                }
            ]
        );
    }
}
