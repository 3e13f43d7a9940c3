//! Unit tests of `language.rs`.

use lang::Lang;
use lesson11::language::*;

fn words(s: &str) -> Vec<String> {
    s.split_whitespace().map(str::to_string).collect()
}

#[test]
fn lang_is_read_from_the_arguments_before_parsing() {
    assert_eq!(from_args(&words("lesson11 --lang bg path")), Some(Lang::Bg));
    assert_eq!(from_args(&words("lesson11 path --lang=en")), Some(Lang::En));
    assert_eq!(from_args(&words("lesson11 path")), None);
    assert_eq!(from_args(&words("lesson11 render -- --lang bg")), None);
}
