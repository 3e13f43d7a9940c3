//! The camera: pinhole and thin lens, from film position to ray and back.
//!
//! Lecture topics: stereoscopy (the stereo rig moves this camera along its
//! `rightDir`), and path construction — camera paths start here, and light
//! tracing connects its light-path vertices back to the lens with the
//! camera's importance `W_e`.
//!
//! Conventions: raster coordinates are in pixels, `x` to the right and `y`
//! downwards, pixel `(i, j)` covers `[i, i+1) × [j, j+1)`. The camera looks
//! along `forward`; image-right is `right_dir = forward × up`, image-up is
//! `up_dir`. The image plane sits at distance 1 in front of the lens and spans
//! `[-tan(fov/2)·aspect, tan(fov/2)·aspect] × [-tan(fov/2), tan(fov/2)]` (the
//! fov is vertical), shifted by `shift` for an off-axis (asymmetric) frustum.

use crate::math::{PI, Ray, RayPdf, Vec2, Vec3A};
use crate::sampling::warp::concentric_disk;

/// What a scene file says about the camera.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraParams {
    /// Centre of the lens (the eye).
    pub position: Vec3A,
    /// The point the camera looks at.
    pub look_at: Vec3A,
    /// Approximate up direction.
    pub up: Vec3A,
    /// Vertical field of view in degrees.
    pub vfov_deg: f32,
    /// Lens radius in metres (0 = pinhole).
    pub aperture_radius: f32,
    /// Distance of the plane in focus, along `forward`.
    pub focus_distance: f32,
    /// Off-axis shift of the image window, in image-plane units at distance 1
    /// (the stereo rig uses it to converge parallel eyes).
    pub shift: Vec2,
}

/// A camera placed in the world, with the image resolution it renders.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    pub params: CameraParams,
    pub width: u32,
    pub height: u32,
    position: Vec3A,
    forward: Vec3A,
    right_dir: Vec3A,
    up_dir: Vec3A,
    /// Half extents of the image window at distance 1.
    half: Vec2,
    /// Area of the image window at distance 1 (`A` in `W_e = 1/(A cos⁴θ)`).
    pub image_area: f32,
}

/// The camera seen from a point in the scene (light tracing's connection to
/// the lens): where the point lands on the film and with which importance.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraSample {
    /// Raster position of the point.
    pub raster: Vec2,
    /// Unit direction from the scene point towards the lens point.
    pub wi: Vec3A,
    /// Distance from the scene point to the lens point.
    pub dist: f32,
    /// The lens point.
    pub p_lens: Vec3A,
    /// Importance `W_e` of the ray from the lens point to the scene point.
    pub we: f32,
    /// Density of `wi` per unit solid angle at the scene point (for a
    /// pinhole, `dist²/cos θ`: the lens "area" is taken as 1).
    pub pdf_w: f32,
}

impl Camera {
    /// Builds the camera frame from `params` for an image of `width × height`.
    ///
    /// # Panics
    /// If the view direction is zero or parallel to `up`, or the size is zero
    /// (the scene loader reports such input as errors before it gets here).
    pub fn new(params: CameraParams, width: u32, height: u32) -> Self {
        assert!(width > 0 && height > 0, "image size must be positive");
        let forward = (params.look_at - params.position).normalize();
        let right_dir = forward.cross(params.up).normalize();
        let up_dir = right_dir.cross(forward);
        assert!(
            forward.is_finite() && right_dir.is_finite(),
            "degenerate camera frame"
        );
        let tan_half = (params.vfov_deg.to_radians() * 0.5).tan();
        let aspect = width as f32 / height as f32;
        let half = Vec2::new(tan_half * aspect, tan_half);
        Camera {
            params,
            width,
            height,
            position: params.position,
            forward,
            right_dir,
            up_dir,
            half,
            image_area: 4.0 * half.x * half.y,
        }
    }

    /// Centre of the lens.
    #[inline]
    pub fn position(&self) -> Vec3A {
        self.position
    }

    /// Unit view direction.
    #[inline]
    pub fn forward(&self) -> Vec3A {
        self.forward
    }

    /// Unit image-right direction (the lecture's `rightDir`): the direction
    /// along which the stereo rig separates the two eyes.
    #[inline]
    pub fn right_dir(&self) -> Vec3A {
        self.right_dir
    }

    /// Unit image-up direction.
    #[inline]
    pub fn up_dir(&self) -> Vec3A {
        self.up_dir
    }

    #[inline]
    fn lens_area(&self) -> f32 {
        let r = self.params.aperture_radius;
        if r > 0.0 { PI * r * r } else { 1.0 }
    }

    #[inline]
    fn lens_point(&self, u_lens: Vec2) -> Vec3A {
        let r = self.params.aperture_radius;
        if r > 0.0 {
            let d = r * concentric_disk(u_lens);
            self.position + d.x * self.right_dir + d.y * self.up_dir
        } else {
            self.position
        }
    }

    /// The primary ray through the raster point `raster` and the lens point
    /// chosen by `u_lens` (ignored by a pinhole).
    #[inline]
    pub fn generate_ray(&self, raster: Vec2, u_lens: Vec2) -> Ray {
        let s = Vec2::new(
            (2.0 * raster.x / self.width as f32 - 1.0) * self.half.x,
            (1.0 - 2.0 * raster.y / self.height as f32) * self.half.y,
        ) + self.params.shift;
        let d = s.x * self.right_dir + s.y * self.up_dir + self.forward;
        if self.params.aperture_radius > 0.0 {
            // Everything on the plane at focus_distance is sharp: aim the ray
            // from the lens point at the pinhole ray's point on that plane.
            let p_focus = self.position + self.params.focus_distance * d;
            let o = self.lens_point(u_lens);
            Ray::new(o, (p_focus - o).normalize())
        } else {
            Ray::new(self.position, d.normalize())
        }
    }

    /// Raster position of the world point `p` seen through the lens point
    /// `p_lens`, or `None` if it is behind the camera or off the film.
    pub fn raster_of(&self, p: Vec3A, p_lens: Vec3A) -> Option<Vec2> {
        let raster = self.raster_beyond_film(p, p_lens)?;
        let inside = raster.x >= 0.0
            && raster.y >= 0.0
            && raster.x < self.width as f32
            && raster.y < self.height as f32;
        inside.then_some(raster)
    }

    /// Raster position of `p` as [`Camera::raster_of`], also where it falls
    /// off the film (outside `[0, W) × [0, H)`: drawings of paths clip it);
    /// `None` only behind the camera.
    pub fn raster_beyond_film(&self, p: Vec3A, p_lens: Vec3A) -> Option<Vec2> {
        let v = p - p_lens;
        let vz = v.dot(self.forward);
        if vz <= 0.0 {
            return None;
        }
        // Where the ray lens→p crosses the image window at distance 1 from
        // the lens centre (for a thin lens: scaled from the plane in focus).
        let s = if self.params.aperture_radius > 0.0 {
            let t = self.params.focus_distance / vz;
            let q = p_lens + t * v - self.position;
            Vec2::new(q.dot(self.right_dir), q.dot(self.up_dir)) / self.params.focus_distance
        } else {
            Vec2::new(v.dot(self.right_dir), v.dot(self.up_dir)) / vz
        } - self.params.shift;
        Some(Vec2::new(
            (s.x / self.half.x + 1.0) * 0.5 * self.width as f32,
            (1.0 - s.y / self.half.y) * 0.5 * self.height as f32,
        ))
    }

    /// Importance `W_e` of a ray leaving the lens in direction `d`:
    /// `1 / (A · A_lens · cos⁴θ)`, with `A` the image window's area at
    /// distance 1 and θ the angle to `forward`. The `cos⁴θ` is the product of
    /// `cos³θ` (the image plane is further away and tilted off-axis: the
    /// solid angle of a film patch shrinks) and `cos θ` (the lens is seen
    /// obliquely), so that integrating `W_e cos θ` over the lens and the
    /// window gives exactly 1 (pbrt-v4, section 16.1.1). Zero off the film.
    pub fn we(&self, ray: &Ray) -> f32 {
        let cos = ray.d.dot(self.forward);
        if cos <= 0.0 {
            return 0.0;
        }
        let p_lens = ray.o;
        let probe = p_lens + ray.d;
        if self.raster_of(probe, p_lens).is_none() {
            return 0.0;
        }
        let cos2 = cos * cos;
        1.0 / (self.image_area * self.lens_area() * cos2 * cos2)
    }

    /// Densities of a ray leaving the lens: the lens point per unit area
    /// (`1/A_lens`) and the direction per unit solid angle (`1/(A cos³θ)`,
    /// the image window mapped to directions); zero off the film.
    pub fn pdf_we(&self, ray: &Ray) -> RayPdf {
        let cos = ray.d.dot(self.forward);
        if cos <= 0.0 || self.raster_of(ray.o + ray.d, ray.o).is_none() {
            return RayPdf {
                pdf_a: 0.0,
                pdf_w: 0.0,
            };
        }
        RayPdf {
            pdf_a: 1.0 / self.lens_area(),
            pdf_w: 1.0 / (self.image_area * cos * cos * cos),
        }
    }

    /// Connects the scene point `p` to the lens (light tracing, and the t = 1
    /// strategies of bidirectional tracing): a lens point from `u_lens`, the
    /// raster position of `p`, and the importance and density of the connection.
    pub fn sample_wi(&self, p: Vec3A, u_lens: Vec2) -> Option<CameraSample> {
        let p_lens = self.lens_point(u_lens);
        let to_lens = p_lens - p;
        let dist2 = to_lens.length_squared();
        let dist = dist2.sqrt();
        if dist == 0.0 {
            return None;
        }
        let wi = to_lens / dist;
        let raster = self.raster_of(p, p_lens)?;
        let ray = Ray::new(p_lens, -wi);
        let we = self.we(&ray);
        let cos_lens = (-wi).dot(self.forward);
        if we == 0.0 || cos_lens <= 0.0 {
            return None;
        }
        // Lens point density per unit area, converted to solid angle at p.
        let pdf_w = dist2 / (cos_lens * self.lens_area());
        Some(CameraSample {
            raster,
            wi,
            dist,
            p_lens,
            we,
            pdf_w,
        })
    }
}
