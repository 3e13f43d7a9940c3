//! Exercise 2 — red–cyan anaglyph with desaturation.
//!
//! Slides: "Anaglyph glasses" ("Анаглифни очила"), "Anaglyphs of saturated
//! scenes" ("Анаглифи на картинки с наситени цветове"), "Desaturation"
//! ("Обезцветяване (desaturation)").
//!
//! Each frame passes through a colour filter, the results are mixed into
//! one frame, and glasses with the same filters let each eye see only its
//! own frame. With saturated colours it helps to "kill" some of the colour
//! first (desaturation).
//!
//! **Part 1: `desaturate(c, d)`.** Design a desaturation by the amount
//! `d ∈ [0, 1]` and show that it has these properties:
//! - `d = 0` leaves the colour as it is; `d = 1` turns it into a grey (the
//!   three channels equal);
//! - for every `d` the colour keeps its luminance `Y(c)`
//!   (`raytracer::math::luminance`, a weighted sum of the linear channels):
//!   each eye sees a colour as bright as before, only less colourful. Which
//!   grey can the colour end at, then?
//! - the colour only loses colourfulness: its difference from the grey it
//!   ends at keeps its direction (the hue does not turn) and never grows as
//!   `d` grows.
//!
//! The grader checks these properties, not one formula.
//!
//! **Part 2: `anaglyph(left, right, d)`.** Mix one pixel of the left frame
//! and the same pixel of the right frame into the pixel of a red–cyan
//! anaglyph (red filter over the left eye, cyan over the right): desaturate
//! both colours by `d` with your part 1, then keep of each what its
//! filter lets through — red for the left eye, green and blue (cyan) for
//! the right.
//!
//! Receives: linear RGB colours and `d`. Returns: the desaturated colour;
//! the anaglyph colour.
//!
//! ---
//!
//! # На български
//!
//! Задача 2 — червено-циан анаглиф с обезцветяване.
//!
//! Слайдове: „Анаглифни очила“, „Анаглифи на картинки с наситени цветове“,
//! „Обезцветяване (desaturation)“.
//!
//! Всеки кадър минава през цветен филтър, резултатите се смесват в един кадър,
//! а очила със същите филтри оставят на всяко око само неговия кадър. При
//! наситени цветове помага първо да „убием“ малко от цвета (обезцветяване,
//! desaturation).
//!
//! **Част 1: `desaturate(c, d)`.** Измислете обезцветяване с количество
//! `d ∈ [0, 1]` и покажете, че то има следните свойства:
//! - `d = 0` оставя цвета какъвто е; `d = 1` го превръща в сиво (трите канала
//!   са равни);
//! - при всяко `d` цветът запазва яркостта си `Y(c)`
//!   (`raytracer::math::luminance`, претеглена сума на линейните канали): всяко
//!   око вижда цвета толкова ярък, колкото преди, само по-малко цветен. До кое
//!   сиво може да стигне тогава цветът?
//! - цветът само губи от цветността си: разликата му от сивото, до което стига,
//!   запазва посоката си (оттенъкът не се завърта) и никога не расте, когато
//!   `d` расте.
//!
//! Проверката гледа тези свойства, а не една формула.
//!
//! **Част 2: `anaglyph(left, right, d)`.** Смесете един пиксел от левия кадър и
//! същия пиксел от десния в пиксел на червено-циан анаглиф (червен филтър пред
//! лявото око, циан — пред дясното): обезцветете двата цвята с `d` чрез част 1,
//! после запазете от всеки това, което пропуска неговият филтър — червеното за
//! лявото око, зеленото и синьото (циан) за дясното.
//!
//! Получава: цветове в линейно RGB и `d`. Връща: обезцветения цвят; цвета на
//! анаглифа.

use raytracer::math::Color;

/// `c` desaturated by `d ∈ [0, 1]`, keeping its luminance.
///
/// `c`, обезцветен с `d ∈ [0, 1]`, със запазена яркост.
pub fn desaturate(c: Color, d: f32) -> Color {
    // TODO: a grey with the right luminance, and a way there that keeps it.
    // TODO (бг): сиво с правилната яркост и път дотам, който я запазва.
    todo!()
}

/// One pixel of a red–cyan anaglyph.
///
/// Един пиксел от червено-циан анаглиф.
pub fn anaglyph(left: Color, right: Color, desaturation: f32) -> Color {
    // TODO: desaturate both colours, then keep what each filter lets through.
    // TODO (бг): обезцветете двата цвята, после запазете това, което пропуска всеки филтър.
    todo!()
}
