//! Unit tests of `commands/slides/html.rs`.

use lesson11::commands::slides::html::*;

#[test]
fn formulas_become_mathml_and_markdown_leaves_them_alone() {
    let html = markdown_to_html(
        "- the BRDF $f_r(\\mathbf{x}, \\omega_i, \\omega_o)$ and `$HOME`\n\n$$\\int_{\\Omega} f_r \\cos\\Theta_o \\, d\\omega_o \\leq 1$$\n",
    )
    .unwrap();
    assert!(html.contains("<li>the BRDF <math>"), "{html}");
    assert!(html.contains("<code>$HOME</code>"), "{html}");
    assert!(html.contains("<math display=\"block\">"), "{html}");
    assert!(
        !html.contains("<p><math display"),
        "display math is not wrapped: {html}"
    );
    assert!(!html.contains("MATHQZ"), "{html}");
    // Underscores inside formulas must not turn into emphasis.
    assert!(!html.contains("<em>"), "{html}");
}

#[test]
fn hand_drawn_figures_leave_the_text_and_join_the_pictures() {
    let html = markdown_to_html(
        "- a $\\omega_i$\n\n<figure class=\"drawing\"><svg viewBox=\"0 0 4 2\"><text>ω<tspan>i</tspan></text></svg><figcaption>c</figcaption></figure>\n",
    )
    .unwrap();
    let (text, drawings) = take_drawings(&html).unwrap();
    assert!(
        text.contains("<li>a <math>") && !text.contains("figure"),
        "{text}"
    );
    assert_eq!(drawings.len(), 1);
    assert!(
        drawings[0].starts_with("<figure class=\"drawing\"><svg viewBox=\"0 0 4 2\">")
            && drawings[0].ends_with("</figure>"),
        "Markdown keeps the drawing as it is: {}",
        drawings[0]
    );
    assert!(take_drawings("<figure class=\"drawing\"><svg>").is_err());
}

#[test]
fn unclosed_and_unknown_formulas_are_errors() {
    assert!(
        markdown_to_html("a $x")
            .unwrap_err()
            .to_string()
            .contains("not closed")
    );
    assert!(
        markdown_to_html("$$x")
            .unwrap_err()
            .to_string()
            .contains("$$")
    );
    assert!(
        markdown_to_html("$\\nope$")
            .unwrap_err()
            .to_string()
            .contains("\\nope")
    );
    assert!(markdown_to_html("costs \\$5").is_ok());
}
