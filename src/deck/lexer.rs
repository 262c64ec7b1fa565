//! Lexemes of namelist text, recognised with nom, one physical line at a time.
//!
//! The grammar above lexemes (assignments, value lists, recovery) is in `namelist.rs`: it needs
//! look-ahead across lines and error recovery, which is clearer written over tokens. Tokens
//! borrow their text from the line: reading a deck copies no names or numbers.

use std::borrow::Cow;

use nom::branch::alt;
use nom::bytes::complete::{tag_no_case, take_while, take_while_m_n};
use nom::character::complete::{char, digit0, digit1, one_of};
use nom::combinator::{consumed, opt, recognize};
use nom::sequence::{pair, tuple};
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

fn is_name_start(c: char) -> bool {
    c.is_ascii_alphabetic()
}

fn is_name_char(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

/// A name: a letter, then letters, digits and `_`.
fn name(i: &str) -> IResult<&str, &str> {
    recognize(pair(
        take_while_m_n(1, 1, is_name_start),
        take_while(is_name_char),
    ))(i)
}

/// `$NAME`, `$END` or a bare `$` (and the same with `&`).
fn open_or_close(i: &str) -> IResult<&str, Tok<'_>> {
    let (rest, _) = one_of("$&")(i)?;
    match name(rest) {
        Ok((after, n)) if n.eq_ignore_ascii_case("END") => Ok((after, Tok::Close)),
        Ok((after, n)) => Ok((after, Tok::Open(upper(n)))),
        Err(_) => Ok((rest, Tok::Close)),
    }
}

/// `.TRUE.`, `.FALSE.`, `.T.` or `.F.`, any case.
fn logical(i: &str) -> IResult<&str, Tok<'_>> {
    let (rest, word) = alt((
        tag_no_case(".TRUE."),
        tag_no_case(".FALSE."),
        tag_no_case(".T."),
        tag_no_case(".F."),
    ))(i)?;
    let value = word.as_bytes()[1].eq_ignore_ascii_case(&b'T');
    Ok((rest, Tok::Logical(value)))
}

fn exponent(i: &str) -> IResult<&str, &str> {
    recognize(tuple((one_of("eEdD"), opt(one_of("+-")), digit1)))(i)
}

fn mantissa(i: &str) -> IResult<&str, &str> {
    alt((
        recognize(pair(digit1, opt(pair(char('.'), digit0)))),
        recognize(pair(char('.'), digit1)),
    ))(i)
}

/// A number: optional sign, digits with an optional `.` and fraction (or `.` and a fraction),
/// optional exponent `E`/`D` with optional sign and digits.
fn number(i: &str) -> IResult<&str, Tok<'_>> {
    let (rest, (text, exp)) = consumed(tuple((opt(one_of("+-")), mantissa, opt(exponent))))(i)?;
    let (_, mantissa_text, exp) = exp;
    let integer = exp.is_none() && !mantissa_text.contains('.');
    // `number` accepts only digits, one dot, sign and exponent, which f64 parses once a
    // Fortran `D` exponent reads `E`; a number beyond the f64 range becomes infinite and the
    // parser reports it.
    let parsed = match exp {
        Some(e) if e.starts_with(['d', 'D']) => text.replace(['d', 'D'], "E").parse::<f64>(),
        _ => text.parse::<f64>(),
    };
    let value = parsed.unwrap_or(f64::INFINITY);
    Ok((
        rest,
        Tok::Number {
            value,
            integer,
            text,
        },
    ))
}

fn punct(i: &str) -> IResult<&str, Tok<'_>> {
    let (rest, c) = one_of("(),=*")(i)?;
    let t = match c {
        '(' => Tok::LParen,
        ')' => Tok::RParen,
        ',' => Tok::Comma,
        '=' => Tok::Equals,
        _ => Tok::Star,
    };
    Ok((rest, t))
}

fn name_token(i: &str) -> IResult<&str, Tok<'_>> {
    name(i).map(|(r, n)| (r, Tok::Name(upper(n))))
}

/// One lexeme and its length in bytes. The first character decides which lexemes can start
/// here (the same choice as trying open/close, logical, number, punctuation and name in turn,
/// without the failed tries); anything that starts none is one character of `Other`.
fn token(i: &str) -> (usize, Tok<'_>) {
    let found = match i.as_bytes()[0] {
        b'$' | b'&' => open_or_close(i),
        b'.' => alt((logical, number))(i),
        b'0'..=b'9' | b'+' | b'-' => number(i),
        b'(' | b')' | b',' | b'=' | b'*' => punct(i),
        _ => name_token(i),
    };
    match found {
        Ok((rest, tok)) => (i.len() - rest.len(), tok),
        Err(_) => {
            let c = i.chars().next().unwrap_or_default();
            (c.len_utf8(), Tok::Other(c))
        }
    }
}

/// A capacity for the tokens of `text` that most lines do not outgrow (values and their commas
/// take two or three characters a token at the least), so that lexing a line does not grow its
/// token list step by step.
pub fn capacity_hint(text: &str) -> usize {
    text.len() / 2 + 1
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
