//! Unit tests of `commands/slides/math.rs`.

use lesson11::commands::slides::math::*;

fn ok(tex: &str) -> String {
    to_mathml(tex, true).unwrap_or_else(|e| panic!("{tex}: {e}"))
}

#[test]
fn the_rendering_equation_converts_with_its_integral_and_bold_points() {
    let m = ok(
        r"L_o(\mathbf{x}, \omega_o) = L_e(\mathbf{x}, \omega_o) + \int_{\Omega} f_r(\mathbf{x}, \omega_i, \omega_o) \, L_i(\mathbf{x}, \omega_i) \, (-\omega_i \cdot \mathbf{n}) \, d\omega_i",
    );
    assert!(m.starts_with("<math display=\"block\">"), "{m}");
    assert!(m.contains("<msub><mi>L</mi><mi>o</mi></msub>"), "{m}");
    assert!(
        m.contains("<msub><mo largeop=\"true\">∫</mo><mi mathvariant=\"normal\">Ω</mi></msub>"),
        "{m}"
    );
    assert!(m.contains("𝐱") && m.contains("𝐧"), "bold x and n: {m}");
    assert!(m.contains("<mo>·</mo>"), "{m}");
    // The sign of −ω_i after the parenthesis is a prefix operator.
    assert!(
        m.contains("<mo stretchy=\"false\">(</mo><mo form=\"prefix\">−</mo>"),
        "{m}"
    );
    let d = ok(r"a - b");
    assert!(d.contains("<mi>a</mi><mo>−</mo><mi>b</mi>"), "{d}");
    assert_eq!(m.matches("<mi>ω</mi>").count(), 7, "{m}");
}

#[test]
fn sums_take_limits_under_and_over_in_display_but_beside_inline() {
    let tex = r"\frac{1}{N} \sum_{k=1}^{N} \frac{f_r}{p(\omega_k)}";
    let block = ok(tex);
    assert!(block.contains("<munderover><mo"), "{block}");
    assert!(
        block.contains("<mfrac><mn>1</mn><mi>N</mi></mfrac>"),
        "{block}"
    );
    let inline = to_mathml(tex, false).unwrap();
    assert!(
        inline.starts_with("<math>") && inline.contains("<msubsup><mo"),
        "{inline}"
    );
}

#[test]
fn cases_become_a_left_aligned_table_with_a_brace_and_text_keeps_its_spaces() {
    let m = ok(
        r"f_r = \begin{cases} \infty, & \omega_o = \mathrm{reflect}(\omega_i) \\ 0, & \text{otherwise} \end{cases}",
    );
    assert!(m.contains("<mtable"), "{m}");
    assert_eq!(m.matches("<mtr>").count(), 2, "{m}");
    assert_eq!(m.matches("<mtd").count(), 4, "{m}");
    assert!(m.contains("<mi>reflect</mi>"), "{m}");
    assert!(m.contains(">{</mo>"), "{m}");
    let t = ok(r"\text{с вероятност } q");
    assert!(t.contains("<mtext>с\u{a0}вероятност\u{a0}</mtext>"), "{t}");
}

#[test]
fn primes_hats_norms_and_scripts_attach_to_their_base() {
    let m = ok(r"L_i(\mathbf{x}, \omega_i) = L_o(\mathbf{x}', -\omega_i)");
    assert!(
        m.contains("<mrow><mi mathvariant=\"normal\">𝐱</mi><mo form=\"postfix\" lspace=\"0\" rspace=\"0\">′</mo></mrow>"),
        "{m}"
    );
    let h = ok(r"E[\hat{I}_N] = I");
    assert!(h.contains("<msub><mover accent=\"true\">"), "{h}");
    let n = ok(r"\lVert \mathbf{x} - \mathbf{y} \rVert^2");
    assert!(
        n.contains("<msup><mo stretchy=\"false\">‖</mo><mn>2</mn></msup>"),
        "{n}"
    );
    let s = ok(r"p_{s,t}^2");
    assert!(s.contains("<msubsup><mi>p</mi><mrow>"), "{s}");
    let c = ok(r"\int_{\mathcal{P}} f(\bar{x}) \, d\mu(\bar{x})");
    assert!(c.contains("𝒫"), "{c}");
}

#[test]
fn numbers_and_markup_characters_are_escaped() {
    let m = ok(r"a < b, 1.5 > 0.25.");
    assert!(
        m.contains("<mo>&lt;</mo>") && m.contains("<mo>&gt;</mo>"),
        "{m}"
    );
    assert!(
        m.contains("<mn>1.5</mn>") && m.contains("<mn>0.25</mn><mo>.</mo>"),
        "{m}"
    );
}

#[test]
fn mistakes_are_errors_that_name_the_problem() {
    for (tex, needle) in [
        (r"\foo{x}", "\\foo"),
        (r"\frac{1}{2", "without"),
        (r"x^", "argument"),
        (r"\begin{align} x \end{align}", "align"),
        (r"\left( x", "\\right"),
        (r"x}", "`}`"),
        (r"_x", "nothing to attach"),
        (r"x_1_2", "double"),
    ] {
        let err = to_mathml(tex, false).expect_err(tex).to_string();
        assert!(err.contains(needle), "{tex}: {err}");
    }
}
