//! The symbol tables of the slides' LaTeX subset: Greek letters, operators
//! and the named functions of the lecture's formulas (`\cos`, `\max`).

/// A lower-case Greek letter by its LaTeX name.
pub fn greek(name: &str) -> Option<char> {
    Some(match name {
        "alpha" => 'α',
        "beta" => 'β',
        "gamma" => 'γ',
        "delta" => 'δ',
        "epsilon" => 'ϵ',
        "varepsilon" => 'ε',
        "zeta" => 'ζ',
        "eta" => 'η',
        "theta" => 'θ',
        "vartheta" => 'ϑ',
        "iota" => 'ι',
        "kappa" => 'κ',
        "lambda" => 'λ',
        "mu" => 'μ',
        "nu" => 'ν',
        "xi" => 'ξ',
        "pi" => 'π',
        "rho" => 'ρ',
        "sigma" => 'σ',
        "tau" => 'τ',
        "upsilon" => 'υ',
        "phi" => 'ϕ',
        "varphi" => 'φ',
        "chi" => 'χ',
        "psi" => 'ψ',
        "omega" => 'ω',
        _ => return None,
    })
}

/// An upper-case Greek letter by its LaTeX name.
pub fn capital_greek(name: &str) -> Option<char> {
    Some(match name {
        "Gamma" => 'Γ',
        "Delta" => 'Δ',
        "Theta" => 'Θ',
        "Lambda" => 'Λ',
        "Xi" => 'Ξ',
        "Pi" => 'Π',
        "Sigma" => 'Σ',
        "Phi" => 'Φ',
        "Psi" => 'Ψ',
        "Omega" => 'Ω',
        _ => return None,
    })
}

/// An operator or delimiter command by name.
pub fn operator(name: &str) -> Option<&'static str> {
    Some(match name {
        "cdot" => "·",
        "cdots" => "⋯",
        "ldots" | "dots" => "…",
        "times" => "×",
        "pm" => "±",
        "mp" => "∓",
        "leq" | "le" => "≤",
        "geq" | "ge" => "≥",
        "neq" | "ne" => "≠",
        "approx" => "≈",
        "sim" => "∼",
        "propto" => "∝",
        "equiv" => "≡",
        "to" | "rightarrow" => "→",
        "leftarrow" | "gets" => "←",
        "Rightarrow" => "⇒",
        "in" => "∈",
        "subset" => "⊂",
        "angle" => "∠",
        "nabla" => "∇",
        "mid" => "∣",
        "{" | "lbrace" => "{",
        "}" | "rbrace" => "}",
        "langle" => "⟨",
        "rangle" => "⟩",
        "lVert" | "rVert" | "|" | "Vert" => "‖",
        _ => return None,
    })
}

/// A named function; `true` if its scripts go under and over it (max, min, lim).
pub fn function(name: &str) -> Option<(&'static str, bool)> {
    Some(match name {
        "cos" => ("cos", false),
        "sin" => ("sin", false),
        "tan" => ("tan", false),
        "exp" => ("exp", false),
        "log" => ("log", false),
        "ln" => ("ln", false),
        "max" => ("max", true),
        "min" => ("min", true),
        "lim" => ("lim", true),
        _ => return None,
    })
}
