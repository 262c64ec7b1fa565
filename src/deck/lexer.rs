//! Lexemes of namelist text, one physical line at a time.
//!
//! The grammar above lexemes (assignments, value lists, recovery) is in `namelist.rs`: it needs
//! look-ahead across lines and error recovery, which is clearer written over tokens. Tokens
//! borrow their text from the line: reading a deck copies no names or numbers.

use std::borrow::Cow;

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

/// Length in bytes of the run of ASCII digits at the start of `b`.
fn digits(b: &[u8]) -> usize {
    b.iter().take_while(|c| c.is_ascii_digit()).count()
}

/// Length of a name (a letter, then letters, digits and `_`) at the start of `b`; 0 for none.
fn name_len(b: &[u8]) -> usize {
    match b.first() {
        Some(c) if c.is_ascii_alphabetic() => {
            1 + b[1..]
                .iter()
                .take_while(|c| c.is_ascii_alphanumeric() || **c == b'_')
                .count()
        }
        _ => 0,
    }
}

/// `$NAME`, `$END` or a bare `$` (and the same with `&`); `i` starts with the sign.
fn open_or_close(i: &str) -> (usize, Tok<'_>) {
    let n = name_len(&i.as_bytes()[1..]);
    let name = &i[1..1 + n];
    if n == 0 || name.eq_ignore_ascii_case("END") {
        (1 + n, Tok::Close)
    } else {
        (1 + n, Tok::Open(upper(name)))
    }
}

/// `.TRUE.`, `.FALSE.`, `.T.` or `.F.`, any case.
fn logical(b: &[u8]) -> Option<(usize, Tok<'static>)> {
    if b.len() < 3 || !b[1].is_ascii_alphabetic() {
        return None;
    }
    [&b".TRUE."[..], b".FALSE.", b".T.", b".F."]
        .iter()
        .find(|word| b.len() >= word.len() && b[..word.len()].eq_ignore_ascii_case(word))
        .map(|word| (word.len(), Tok::Logical(word[1] == b'T')))
}

/// A number: optional sign, digits with an optional `.` and fraction (or `.` and a fraction),
/// optional exponent `E`/`D` with optional sign and digits.
fn number(i: &str) -> Option<(usize, Tok<'_>)> {
    let b = i.as_bytes();
    let mut k = usize::from(matches!(b.first(), Some(b'+' | b'-')));
    let whole = digits(&b[k..]);
    let mut dot = false;
    if whole > 0 {
        k += whole;
        if b.get(k) == Some(&b'.') {
            dot = true;
            k += 1 + digits(&b[k + 1..]);
        }
    } else if b.get(k) == Some(&b'.') && digits(&b[k + 1..]) > 0 {
        dot = true;
        k += 1 + digits(&b[k + 1..]);
    } else {
        return None;
    }
    let mut exponent = None;
    if let Some(e @ (b'e' | b'E' | b'd' | b'D')) = b.get(k) {
        let sign = usize::from(matches!(b.get(k + 1), Some(b'+' | b'-')));
        let n = digits(&b[k + 1 + sign..]);
        if n > 0 {
            exponent = Some(*e);
            k += 1 + sign + n;
        }
    }
    let text = &i[..k];
    let integer = !dot && exponent.is_none();
    // The text holds only digits, one dot, sign and exponent, which f64 parses once a Fortran
    // `D` exponent reads `E`; a number beyond the f64 range becomes infinite and the parser
    // reports it.
    let parsed = if let Some(b'd' | b'D') = exponent {
        text.replace(['d', 'D'], "E").parse::<f64>()
    } else {
        text.parse::<f64>()
    };
    let value = parsed.unwrap_or(f64::INFINITY);
    Some((
        k,
        Tok::Number {
            value,
            integer,
            text,
        },
    ))
}

/// One lexeme and its length in bytes. The first character decides which lexemes can start
/// here; anything that starts none is one character of `Other`.
fn token(i: &str) -> (usize, Tok<'_>) {
    let b = i.as_bytes();
    let found = match b[0] {
        b'$' | b'&' => Some(open_or_close(i)),
        b'.' => logical(b).or_else(|| number(i)),
        b'0'..=b'9' | b'+' | b'-' => number(i),
        b'(' => Some((1, Tok::LParen)),
        b')' => Some((1, Tok::RParen)),
        b',' => Some((1, Tok::Comma)),
        b'=' => Some((1, Tok::Equals)),
        b'*' => Some((1, Tok::Star)),
        _ => match name_len(b) {
            0 => None,
            n => Some((n, Tok::Name(upper(&i[..n])))),
        },
    };
    found.unwrap_or_else(|| {
        let c = i.chars().next().unwrap_or_default();
        (c.len_utf8(), Tok::Other(c))
    })
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
