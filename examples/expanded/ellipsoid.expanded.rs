/// A heavy ellipsoid on a smooth horizontal plane (paper Example 2, errata E1, E2, E6).
#[derive(Lagrangian)]
#[lagrangian(
    let
    d = diag(semi_axes.component_mul(semi_axes)),
    let
    c3 = gamma.dot(d*gamma).sqrt()-offset.dot(gamma),
    let
    n = grad(c3, gamma),
    kinetic = 0.5*(
        omega.dot(diag(inertia)*omega)+mass*n.dot(gamma.cross(omega)).powi(2)
    ),
    potential = mass*g*c3,
)]
pub struct DiagonalEllipsoid {
    /// Principal moments of inertia `(I₁, I₂, I₃)`.
    pub inertia: Vector3<f64>,
    /// Semi-axes `(a₁, a₂, a₃)`.
    pub semi_axes: Vector3<f64>,
    /// Position `c₀` of the ellipsoid's centre relative to the centre of mass.
    pub offset: Vector3<f64>,
    /// Mass `m`.
    pub mass: f64,
    /// Gravity `g`.
    pub g: f64,
}
#[doc(hidden)]
#[allow(
    non_upper_case_globals,
    unused_qualifications,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
const _: () = {
    type __F64 = ::routh::__private::f64;
    type __Vector3 = ::routh::__private::Vector3<::routh::__private::f64>;
    type __Matrix3 = ::routh::__private::Matrix3<::routh::__private::f64>;
    type __RouthBundle = ::routh::__private::RouthBundle;
    type __GyroscopicSystem = ::routh::__private::GyroscopicSystem;
    type __FullEquations = ::routh::__private::FullEquations;
    type __ReducedEquations = ::routh::__private::ReducedEquations;
    type __RouthTape = ::routh::__private::RouthTape;
    type __MaybeTape = ::routh::__private::MaybeTape;
    type __MaybeMatrix3 = ::routh::__private::MaybeMatrix3;
    type __RankOneInertia = ::routh::__private::RankOneInertia;
    type __MaybeRankOne = ::routh::__private::MaybeRankOne;
    #[automatically_derived]
    impl ::routh::__private::Lagrangian for DiagonalEllipsoid {
        #[inline]
        fn lagrangian(&self, __omega: &__Vector3, __gamma: &__Vector3) -> __F64 {
            let __v0: __F64 = __omega[0usize];
            let __v1: __F64 = __omega[1usize];
            let __v2: __F64 = __omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v7: __F64 = self.inertia[0usize];
            let __v8: __F64 = self.inertia[1usize];
            let __v9: __F64 = self.inertia[2usize];
            let __v10: __F64 = self.semi_axes[0usize];
            let __v11: __F64 = self.semi_axes[1usize];
            let __v12: __F64 = self.semi_axes[2usize];
            let __v13: __F64 = self.offset[0usize];
            let __v14: __F64 = self.offset[1usize];
            let __v15: __F64 = self.offset[2usize];
            let __v16: __F64 = self.mass;
            let __v17: __F64 = self.g;
            let __t18 = __v10 * __v10;
            let __t19 = __v11 * __v11;
            let __t20 = __v12 * __v12;
            let __t22 = __v3 * __t18;
            let __t23 = __v4 * __t19;
            let __t24 = __v5 * __t20;
            let __t25 = __v3 * __t22;
            let __t26 = __v4 * __t23;
            let __t27 = __v5 * __t24;
            let __t28 = __t25 + __t26;
            let __t29 = __t27 + __t28;
            let __t30 = __t29.sqrt();
            let __t31 = __v3 * __v13;
            let __t32 = __v4 * __v14;
            let __t33 = __v5 * __v15;
            let __t34 = __t31 + __t32;
            let __t35 = __t33 + __t34;
            let __t37 = __t30 - __t35;
            let __t43 = 1.0f64 / __t30;
            let __t45 = __t22 * __t43;
            let __t47 = __t45 - __v13;
            let __t50 = __t23 * __t43;
            let __t52 = __t50 - __v14;
            let __t55 = __t24 * __t43;
            let __t57 = __t55 - __v15;
            let __t58 = __v0 * __v7;
            let __t59 = __v1 * __v8;
            let __t60 = __v2 * __v9;
            let __t61 = __v0 * __t58;
            let __t62 = __v1 * __t59;
            let __t63 = __v2 * __t60;
            let __t64 = __t61 + __t62;
            let __t65 = __t63 + __t64;
            let __t66 = __v2 * __v4;
            let __t67 = __v1 * __v5;
            let __t69 = __t66 - __t67;
            let __t70 = __v0 * __v5;
            let __t71 = __v2 * __v3;
            let __t73 = __t70 - __t71;
            let __t74 = __v1 * __v3;
            let __t75 = __v0 * __v4;
            let __t77 = __t74 - __t75;
            let __t78 = __t47 * __t69;
            let __t79 = __t52 * __t73;
            let __t80 = __t57 * __t77;
            let __t81 = __t78 + __t79;
            let __t82 = __t80 + __t81;
            let __t83 = __t82 * __t82;
            let __t84 = __v16 * __t83;
            let __t85 = __t65 + __t84;
            let __t86 = 0.5f64 * __t85;
            let __t87 = __v16 * __v17;
            let __t88 = __t37 * __t87;
            let __t90 = __t86 - __t88;
            __t90
        }
        #[inline]
        fn dl_domega(&self, __omega: &__Vector3, __gamma: &__Vector3) -> __Vector3 {
            let __v0: __F64 = __omega[0usize];
            let __v1: __F64 = __omega[1usize];
            let __v2: __F64 = __omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v7: __F64 = self.inertia[0usize];
            let __v8: __F64 = self.inertia[1usize];
            let __v9: __F64 = self.inertia[2usize];
            let __v10: __F64 = self.semi_axes[0usize];
            let __v11: __F64 = self.semi_axes[1usize];
            let __v12: __F64 = self.semi_axes[2usize];
            let __v13: __F64 = self.offset[0usize];
            let __v14: __F64 = self.offset[1usize];
            let __v15: __F64 = self.offset[2usize];
            let __v16: __F64 = self.mass;
            let __t18 = __v10 * __v10;
            let __t19 = __v11 * __v11;
            let __t20 = __v12 * __v12;
            let __t22 = __v3 * __t18;
            let __t23 = __v4 * __t19;
            let __t24 = __v5 * __t20;
            let __t25 = __v3 * __t22;
            let __t26 = __v4 * __t23;
            let __t27 = __v5 * __t24;
            let __t28 = __t25 + __t26;
            let __t29 = __t27 + __t28;
            let __t30 = __t29.sqrt();
            let __t43 = 1.0f64 / __t30;
            let __t45 = __t22 * __t43;
            let __t47 = __t45 - __v13;
            let __t50 = __t23 * __t43;
            let __t52 = __t50 - __v14;
            let __t55 = __t24 * __t43;
            let __t57 = __t55 - __v15;
            let __t58 = __v0 * __v7;
            let __t59 = __v1 * __v8;
            let __t60 = __v2 * __v9;
            let __t66 = __v2 * __v4;
            let __t67 = __v1 * __v5;
            let __t69 = __t66 - __t67;
            let __t70 = __v0 * __v5;
            let __t71 = __v2 * __v3;
            let __t73 = __t70 - __t71;
            let __t74 = __v1 * __v3;
            let __t75 = __v0 * __v4;
            let __t77 = __t74 - __t75;
            let __t78 = __t47 * __t69;
            let __t79 = __t52 * __t73;
            let __t80 = __t57 * __t77;
            let __t81 = __t78 + __t79;
            let __t82 = __t80 + __t81;
            let __t91 = __v5 * __t52;
            let __t93 = __v4 * __t57;
            let __t95 = __t91 - __t93;
            let __t97 = __t82 * __t95;
            let __t99 = __v16 * __t97;
            let __t103 = __t58 + __t99;
            let __t105 = __v5 * __t47;
            let __t107 = __v3 * __t57;
            let __t108 = __t107 - __t105;
            let __t109 = __t82 * __t108;
            let __t111 = __v16 * __t109;
            let __t115 = __t59 + __t111;
            let __t117 = __v3 * __t52;
            let __t119 = __v4 * __t47;
            let __t120 = __t119 - __t117;
            let __t121 = __t82 * __t120;
            let __t123 = __v16 * __t121;
            let __t127 = __t60 + __t123;
            __Vector3::new(__t103, __t115, __t127)
        }
        #[inline]
        fn dl_dgamma(&self, __omega: &__Vector3, __gamma: &__Vector3) -> __Vector3 {
            let __v0: __F64 = __omega[0usize];
            let __v1: __F64 = __omega[1usize];
            let __v2: __F64 = __omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v10: __F64 = self.semi_axes[0usize];
            let __v11: __F64 = self.semi_axes[1usize];
            let __v12: __F64 = self.semi_axes[2usize];
            let __v13: __F64 = self.offset[0usize];
            let __v14: __F64 = self.offset[1usize];
            let __v15: __F64 = self.offset[2usize];
            let __v16: __F64 = self.mass;
            let __v17: __F64 = self.g;
            let __t18 = __v10 * __v10;
            let __t19 = __v11 * __v11;
            let __t20 = __v12 * __v12;
            let __t22 = __v3 * __t18;
            let __t23 = __v4 * __t19;
            let __t24 = __v5 * __t20;
            let __t25 = __v3 * __t22;
            let __t26 = __v4 * __t23;
            let __t27 = __v5 * __t24;
            let __t28 = __t25 + __t26;
            let __t29 = __t27 + __t28;
            let __t30 = __t29.sqrt();
            let __t43 = 1.0f64 / __t30;
            let __t45 = __t22 * __t43;
            let __t47 = __t45 - __v13;
            let __t50 = __t23 * __t43;
            let __t52 = __t50 - __v14;
            let __t55 = __t24 * __t43;
            let __t57 = __t55 - __v15;
            let __t66 = __v2 * __v4;
            let __t67 = __v1 * __v5;
            let __t69 = __t66 - __t67;
            let __t70 = __v0 * __v5;
            let __t71 = __v2 * __v3;
            let __t73 = __t70 - __t71;
            let __t74 = __v1 * __v3;
            let __t75 = __v0 * __v4;
            let __t77 = __t74 - __t75;
            let __t78 = __t47 * __t69;
            let __t79 = __t52 * __t73;
            let __t80 = __t57 * __t77;
            let __t81 = __t78 + __t79;
            let __t82 = __t80 + __t81;
            let __t87 = __v16 * __v17;
            let __t128 = __t47 * __t87;
            let __t131 = __t43 * __t43;
            let __t132 = __t45 * __t131;
            let __t134 = __t23 * __t132;
            let __t136 = __t73 * __t134;
            let __t138 = __v2 * __t52;
            let __t140 = __t136 + __t138;
            let __t142 = __t18 * __t43;
            let __t143 = __t22 * __t132;
            let __t145 = __t142 - __t143;
            let __t146 = __t69 * __t145;
            let __t147 = __t146 - __t140;
            let __t148 = __t24 * __t132;
            let __t150 = __t77 * __t148;
            let __t152 = __v1 * __t57;
            let __t153 = __t152 - __t150;
            let __t154 = __t147 + __t153;
            let __t155 = __t82 * __t154;
            let __t157 = __v16 * __t155;
            let __t159 = __t157 - __t128;
            let __t160 = __t52 * __t87;
            let __t162 = __t50 * __t131;
            let __t164 = __t19 * __t43;
            let __t165 = __t23 * __t162;
            let __t167 = __t164 - __t165;
            let __t168 = __t73 * __t167;
            let __t169 = __t22 * __t162;
            let __t171 = __t69 * __t169;
            let __t173 = __v2 * __t47;
            let __t174 = __t173 - __t171;
            let __t175 = __t168 + __t174;
            let __t177 = __t24 * __t162;
            let __t179 = __t77 * __t177;
            let __t181 = __v0 * __t57;
            let __t183 = __t179 + __t181;
            let __t185 = __t175 - __t183;
            let __t186 = __t82 * __t185;
            let __t188 = __v16 * __t186;
            let __t190 = __t188 - __t160;
            let __t191 = __t57 * __t87;
            let __t193 = __t55 * __t131;
            let __t195 = __t23 * __t193;
            let __t197 = __t73 * __t195;
            let __t199 = __v0 * __t52;
            let __t200 = __t199 - __t197;
            let __t202 = __t22 * __t193;
            let __t204 = __t69 * __t202;
            let __t206 = __v1 * __t47;
            let __t208 = __t204 + __t206;
            let __t210 = __t200 - __t208;
            let __t211 = __t20 * __t43;
            let __t212 = __t24 * __t193;
            let __t214 = __t211 - __t212;
            let __t215 = __t77 * __t214;
            let __t216 = __t210 + __t215;
            let __t217 = __t82 * __t216;
            let __t219 = __v16 * __t217;
            let __t221 = __t219 - __t191;
            __Vector3::new(__t159, __t190, __t221)
        }
        #[inline]
        fn d2l_domega2(&self, __gamma: &__Vector3) -> __Matrix3 {
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v7: __F64 = self.inertia[0usize];
            let __v8: __F64 = self.inertia[1usize];
            let __v9: __F64 = self.inertia[2usize];
            let __v10: __F64 = self.semi_axes[0usize];
            let __v11: __F64 = self.semi_axes[1usize];
            let __v12: __F64 = self.semi_axes[2usize];
            let __v13: __F64 = self.offset[0usize];
            let __v14: __F64 = self.offset[1usize];
            let __v15: __F64 = self.offset[2usize];
            let __v16: __F64 = self.mass;
            let __t18 = __v10 * __v10;
            let __t19 = __v11 * __v11;
            let __t20 = __v12 * __v12;
            let __t22 = __v3 * __t18;
            let __t23 = __v4 * __t19;
            let __t24 = __v5 * __t20;
            let __t25 = __v3 * __t22;
            let __t26 = __v4 * __t23;
            let __t27 = __v5 * __t24;
            let __t28 = __t25 + __t26;
            let __t29 = __t27 + __t28;
            let __t30 = __t29.sqrt();
            let __t43 = 1.0f64 / __t30;
            let __t45 = __t22 * __t43;
            let __t47 = __t45 - __v13;
            let __t50 = __t23 * __t43;
            let __t52 = __t50 - __v14;
            let __t55 = __t24 * __t43;
            let __t57 = __t55 - __v15;
            let __t91 = __v5 * __t52;
            let __t93 = __v4 * __t57;
            let __t95 = __t91 - __t93;
            let __t105 = __v5 * __t47;
            let __t107 = __v3 * __t57;
            let __t108 = __t107 - __t105;
            let __t117 = __v3 * __t52;
            let __t119 = __v4 * __t47;
            let __t120 = __t119 - __t117;
            let __t222 = __t95 * __t95;
            let __t223 = __v16 * __t222;
            let __t224 = __v7 + __t223;
            let __t225 = __t95 * __t108;
            let __t226 = __v16 * __t225;
            let __t227 = __t95 * __t120;
            let __t228 = __v16 * __t227;
            let __t229 = __t108 * __t108;
            let __t230 = __v16 * __t229;
            let __t231 = __v8 + __t230;
            let __t232 = __t108 * __t120;
            let __t233 = __v16 * __t232;
            let __t234 = __t120 * __t120;
            let __t235 = __v16 * __t234;
            let __t236 = __v9 + __t235;
            __Matrix3::new(
                __t224,
                __t226,
                __t228,
                __t226,
                __t231,
                __t233,
                __t228,
                __t233,
                __t236,
            )
        }
        #[inline]
        fn d2l_domega_dgamma(
            &self,
            __omega: &__Vector3,
            __gamma: &__Vector3,
        ) -> __Matrix3 {
            let __v0: __F64 = __omega[0usize];
            let __v1: __F64 = __omega[1usize];
            let __v2: __F64 = __omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v10: __F64 = self.semi_axes[0usize];
            let __v11: __F64 = self.semi_axes[1usize];
            let __v12: __F64 = self.semi_axes[2usize];
            let __v13: __F64 = self.offset[0usize];
            let __v14: __F64 = self.offset[1usize];
            let __v15: __F64 = self.offset[2usize];
            let __v16: __F64 = self.mass;
            let __t18 = __v10 * __v10;
            let __t19 = __v11 * __v11;
            let __t20 = __v12 * __v12;
            let __t22 = __v3 * __t18;
            let __t23 = __v4 * __t19;
            let __t24 = __v5 * __t20;
            let __t25 = __v3 * __t22;
            let __t26 = __v4 * __t23;
            let __t27 = __v5 * __t24;
            let __t28 = __t25 + __t26;
            let __t29 = __t27 + __t28;
            let __t30 = __t29.sqrt();
            let __t43 = 1.0f64 / __t30;
            let __t45 = __t22 * __t43;
            let __t47 = __t45 - __v13;
            let __t50 = __t23 * __t43;
            let __t52 = __t50 - __v14;
            let __t55 = __t24 * __t43;
            let __t57 = __t55 - __v15;
            let __t66 = __v2 * __v4;
            let __t67 = __v1 * __v5;
            let __t69 = __t66 - __t67;
            let __t70 = __v0 * __v5;
            let __t71 = __v2 * __v3;
            let __t73 = __t70 - __t71;
            let __t74 = __v1 * __v3;
            let __t75 = __v0 * __v4;
            let __t77 = __t74 - __t75;
            let __t78 = __t47 * __t69;
            let __t79 = __t52 * __t73;
            let __t80 = __t57 * __t77;
            let __t81 = __t78 + __t79;
            let __t82 = __t80 + __t81;
            let __t91 = __v5 * __t52;
            let __t93 = __v4 * __t57;
            let __t95 = __t91 - __t93;
            let __t105 = __v5 * __t47;
            let __t107 = __v3 * __t57;
            let __t108 = __t107 - __t105;
            let __t117 = __v3 * __t52;
            let __t119 = __v4 * __t47;
            let __t120 = __t119 - __t117;
            let __t131 = __t43 * __t43;
            let __t132 = __t45 * __t131;
            let __t134 = __t23 * __t132;
            let __t136 = __t73 * __t134;
            let __t138 = __v2 * __t52;
            let __t140 = __t136 + __t138;
            let __t142 = __t18 * __t43;
            let __t143 = __t22 * __t132;
            let __t145 = __t142 - __t143;
            let __t146 = __t69 * __t145;
            let __t147 = __t146 - __t140;
            let __t148 = __t24 * __t132;
            let __t150 = __t77 * __t148;
            let __t152 = __v1 * __t57;
            let __t153 = __t152 - __t150;
            let __t154 = __t147 + __t153;
            let __t162 = __t50 * __t131;
            let __t164 = __t19 * __t43;
            let __t165 = __t23 * __t162;
            let __t167 = __t164 - __t165;
            let __t168 = __t73 * __t167;
            let __t169 = __t22 * __t162;
            let __t171 = __t69 * __t169;
            let __t173 = __v2 * __t47;
            let __t174 = __t173 - __t171;
            let __t175 = __t168 + __t174;
            let __t177 = __t24 * __t162;
            let __t179 = __t77 * __t177;
            let __t181 = __v0 * __t57;
            let __t183 = __t179 + __t181;
            let __t185 = __t175 - __t183;
            let __t193 = __t55 * __t131;
            let __t195 = __t23 * __t193;
            let __t197 = __t73 * __t195;
            let __t199 = __v0 * __t52;
            let __t200 = __t199 - __t197;
            let __t202 = __t22 * __t193;
            let __t204 = __t69 * __t202;
            let __t206 = __v1 * __t47;
            let __t208 = __t204 + __t206;
            let __t210 = __t200 - __t208;
            let __t211 = __t20 * __t43;
            let __t212 = __t24 * __t193;
            let __t214 = __t211 - __t212;
            let __t215 = __t77 * __t214;
            let __t216 = __t210 + __t215;
            let __t237 = __v4 * __t148;
            let __t239 = __v5 * __t134;
            let __t241 = __t237 - __t239;
            let __t242 = __t95 * __t154;
            let __t243 = __t82 * __t241;
            let __t244 = __t242 + __t243;
            let __t245 = __v16 * __t244;
            let __t246 = __v4 * __t177;
            let __t248 = __t57 - __t246;
            let __t250 = __v5 * __t167;
            let __t251 = __t250 - __t248;
            let __t252 = __t95 * __t185;
            let __t253 = __t82 * __t251;
            let __t254 = __t252 + __t253;
            let __t255 = __v16 * __t254;
            let __t256 = __v4 * __t214;
            let __t258 = __v5 * __t195;
            let __t260 = __t52 - __t258;
            let __t261 = __t260 - __t256;
            let __t262 = __t95 * __t216;
            let __t263 = __t82 * __t261;
            let __t264 = __t262 + __t263;
            let __t265 = __v16 * __t264;
            let __t266 = __v3 * __t148;
            let __t268 = __t57 - __t266;
            let __t269 = __v5 * __t145;
            let __t271 = __t268 - __t269;
            let __t272 = __t108 * __t154;
            let __t273 = __t82 * __t271;
            let __t274 = __t272 + __t273;
            let __t275 = __v16 * __t274;
            let __t276 = __v3 * __t177;
            let __t278 = __v5 * __t169;
            let __t280 = __t278 - __t276;
            let __t281 = __t108 * __t185;
            let __t282 = __t82 * __t280;
            let __t283 = __t281 + __t282;
            let __t284 = __v16 * __t283;
            let __t285 = __v3 * __t214;
            let __t286 = __v5 * __t202;
            let __t288 = __t47 - __t286;
            let __t290 = __t285 - __t288;
            let __t291 = __t108 * __t216;
            let __t292 = __t82 * __t290;
            let __t293 = __t291 + __t292;
            let __t294 = __v16 * __t293;
            let __t295 = __v4 * __t145;
            let __t296 = __v3 * __t134;
            let __t298 = __t52 - __t296;
            let __t300 = __t295 - __t298;
            let __t301 = __t120 * __t154;
            let __t302 = __t82 * __t300;
            let __t303 = __t301 + __t302;
            let __t304 = __v16 * __t303;
            let __t305 = __v4 * __t169;
            let __t307 = __t47 - __t305;
            let __t308 = __v3 * __t167;
            let __t310 = __t307 - __t308;
            let __t311 = __t120 * __t185;
            let __t312 = __t82 * __t310;
            let __t313 = __t311 + __t312;
            let __t314 = __v16 * __t313;
            let __t315 = __v4 * __t202;
            let __t317 = __v3 * __t195;
            let __t319 = __t317 - __t315;
            let __t320 = __t120 * __t216;
            let __t321 = __t82 * __t319;
            let __t322 = __t320 + __t321;
            let __t323 = __v16 * __t322;
            __Matrix3::new(
                __t245,
                __t255,
                __t265,
                __t275,
                __t284,
                __t294,
                __t304,
                __t314,
                __t323,
            )
        }
        #[inline]
        fn energy(&self, __omega: &__Vector3, __gamma: &__Vector3) -> __F64 {
            let __v0: __F64 = __omega[0usize];
            let __v1: __F64 = __omega[1usize];
            let __v2: __F64 = __omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v7: __F64 = self.inertia[0usize];
            let __v8: __F64 = self.inertia[1usize];
            let __v9: __F64 = self.inertia[2usize];
            let __v10: __F64 = self.semi_axes[0usize];
            let __v11: __F64 = self.semi_axes[1usize];
            let __v12: __F64 = self.semi_axes[2usize];
            let __v13: __F64 = self.offset[0usize];
            let __v14: __F64 = self.offset[1usize];
            let __v15: __F64 = self.offset[2usize];
            let __v16: __F64 = self.mass;
            let __v17: __F64 = self.g;
            let __t18 = __v10 * __v10;
            let __t19 = __v11 * __v11;
            let __t20 = __v12 * __v12;
            let __t22 = __v3 * __t18;
            let __t23 = __v4 * __t19;
            let __t24 = __v5 * __t20;
            let __t25 = __v3 * __t22;
            let __t26 = __v4 * __t23;
            let __t27 = __v5 * __t24;
            let __t28 = __t25 + __t26;
            let __t29 = __t27 + __t28;
            let __t30 = __t29.sqrt();
            let __t31 = __v3 * __v13;
            let __t32 = __v4 * __v14;
            let __t33 = __v5 * __v15;
            let __t34 = __t31 + __t32;
            let __t35 = __t33 + __t34;
            let __t37 = __t30 - __t35;
            let __t43 = 1.0f64 / __t30;
            let __t45 = __t22 * __t43;
            let __t47 = __t45 - __v13;
            let __t50 = __t23 * __t43;
            let __t52 = __t50 - __v14;
            let __t55 = __t24 * __t43;
            let __t57 = __t55 - __v15;
            let __t58 = __v0 * __v7;
            let __t59 = __v1 * __v8;
            let __t60 = __v2 * __v9;
            let __t61 = __v0 * __t58;
            let __t62 = __v1 * __t59;
            let __t63 = __v2 * __t60;
            let __t64 = __t61 + __t62;
            let __t65 = __t63 + __t64;
            let __t66 = __v2 * __v4;
            let __t67 = __v1 * __v5;
            let __t69 = __t66 - __t67;
            let __t70 = __v0 * __v5;
            let __t71 = __v2 * __v3;
            let __t73 = __t70 - __t71;
            let __t74 = __v1 * __v3;
            let __t75 = __v0 * __v4;
            let __t77 = __t74 - __t75;
            let __t78 = __t47 * __t69;
            let __t79 = __t52 * __t73;
            let __t80 = __t57 * __t77;
            let __t81 = __t78 + __t79;
            let __t82 = __t80 + __t81;
            let __t83 = __t82 * __t82;
            let __t84 = __v16 * __t83;
            let __t85 = __t65 + __t84;
            let __t86 = 0.5f64 * __t85;
            let __t87 = __v16 * __v17;
            let __t88 = __t37 * __t87;
            let __t90 = __t86 - __t88;
            let __t91 = __v5 * __t52;
            let __t93 = __v4 * __t57;
            let __t95 = __t91 - __t93;
            let __t97 = __t82 * __t95;
            let __t99 = __v16 * __t97;
            let __t103 = __t58 + __t99;
            let __t105 = __v5 * __t47;
            let __t107 = __v3 * __t57;
            let __t108 = __t107 - __t105;
            let __t109 = __t82 * __t108;
            let __t111 = __v16 * __t109;
            let __t115 = __t59 + __t111;
            let __t117 = __v3 * __t52;
            let __t119 = __v4 * __t47;
            let __t120 = __t119 - __t117;
            let __t121 = __t82 * __t120;
            let __t123 = __v16 * __t121;
            let __t127 = __t60 + __t123;
            let __t324 = __v0 * __t103;
            let __t325 = __v1 * __t115;
            let __t326 = __v2 * __t127;
            let __t327 = __t324 + __t325;
            let __t328 = __t326 + __t327;
            let __t330 = __t328 - __t90;
            __t330
        }
        #[inline]
        fn cyclic_momentum(&self, __omega: &__Vector3, __gamma: &__Vector3) -> __F64 {
            let __v0: __F64 = __omega[0usize];
            let __v1: __F64 = __omega[1usize];
            let __v2: __F64 = __omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v7: __F64 = self.inertia[0usize];
            let __v8: __F64 = self.inertia[1usize];
            let __v9: __F64 = self.inertia[2usize];
            let __t58 = __v0 * __v7;
            let __t59 = __v1 * __v8;
            let __t60 = __v2 * __v9;
            let __t336 = __v3 * __v7;
            let __t337 = __v4 * __v8;
            let __t338 = __v5 * __v9;
            let __t1667 = __v4 * __t59;
            let __t1668 = __v1 * __t337;
            let __t1669 = __t1667 + __t1668;
            let __t1670 = __v3 * __t58;
            let __t1671 = __v0 * __t336;
            let __t1672 = __t1670 + __t1671;
            let __t1673 = __t1669 + __t1672;
            let __t1674 = __v5 * __t60;
            let __t1675 = __v2 * __t338;
            let __t1676 = __t1674 + __t1675;
            let __t1677 = __t1673 + __t1676;
            let __t1678 = 0.5f64 * __t1677;
            __t1678
        }
        #[inline]
        fn constant_inertia(&self) -> __MaybeMatrix3 {
            let __v7: __F64 = self.inertia[0usize];
            let __v8: __F64 = self.inertia[1usize];
            let __v9: __F64 = self.inertia[2usize];
            __MaybeMatrix3::Some(
                __Matrix3::new(__v7, 0f64, 0f64, 0f64, __v8, 0f64, 0f64, 0f64, __v9),
            )
        }
        #[inline]
        fn full_equations(
            &self,
            __omega: &__Vector3,
            __gamma: &__Vector3,
        ) -> __FullEquations {
            let __v0: __F64 = __omega[0usize];
            let __v1: __F64 = __omega[1usize];
            let __v2: __F64 = __omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v7: __F64 = self.inertia[0usize];
            let __v8: __F64 = self.inertia[1usize];
            let __v9: __F64 = self.inertia[2usize];
            let __v10: __F64 = self.semi_axes[0usize];
            let __v11: __F64 = self.semi_axes[1usize];
            let __v12: __F64 = self.semi_axes[2usize];
            let __v13: __F64 = self.offset[0usize];
            let __v14: __F64 = self.offset[1usize];
            let __v15: __F64 = self.offset[2usize];
            let __v16: __F64 = self.mass;
            let __v17: __F64 = self.g;
            let __t18 = __v10 * __v10;
            let __t19 = __v11 * __v11;
            let __t20 = __v12 * __v12;
            let __t22 = __v3 * __t18;
            let __t23 = __v4 * __t19;
            let __t24 = __v5 * __t20;
            let __t25 = __v3 * __t22;
            let __t26 = __v4 * __t23;
            let __t27 = __v5 * __t24;
            let __t28 = __t25 + __t26;
            let __t29 = __t27 + __t28;
            let __t30 = __t29.sqrt();
            let __t43 = 1.0f64 / __t30;
            let __t45 = __t22 * __t43;
            let __t47 = __t45 - __v13;
            let __t50 = __t23 * __t43;
            let __t52 = __t50 - __v14;
            let __t55 = __t24 * __t43;
            let __t57 = __t55 - __v15;
            let __t58 = __v0 * __v7;
            let __t59 = __v1 * __v8;
            let __t60 = __v2 * __v9;
            let __t66 = __v2 * __v4;
            let __t67 = __v1 * __v5;
            let __t69 = __t66 - __t67;
            let __t70 = __v0 * __v5;
            let __t71 = __v2 * __v3;
            let __t73 = __t70 - __t71;
            let __t74 = __v1 * __v3;
            let __t75 = __v0 * __v4;
            let __t77 = __t74 - __t75;
            let __t78 = __t47 * __t69;
            let __t79 = __t52 * __t73;
            let __t80 = __t57 * __t77;
            let __t81 = __t78 + __t79;
            let __t82 = __t80 + __t81;
            let __t87 = __v16 * __v17;
            let __t91 = __v5 * __t52;
            let __t93 = __v4 * __t57;
            let __t95 = __t91 - __t93;
            let __t97 = __t82 * __t95;
            let __t99 = __v16 * __t97;
            let __t103 = __t58 + __t99;
            let __t105 = __v5 * __t47;
            let __t107 = __v3 * __t57;
            let __t108 = __t107 - __t105;
            let __t109 = __t82 * __t108;
            let __t111 = __v16 * __t109;
            let __t115 = __t59 + __t111;
            let __t117 = __v3 * __t52;
            let __t119 = __v4 * __t47;
            let __t120 = __t119 - __t117;
            let __t121 = __t82 * __t120;
            let __t123 = __v16 * __t121;
            let __t127 = __t60 + __t123;
            let __t128 = __t47 * __t87;
            let __t131 = __t43 * __t43;
            let __t132 = __t45 * __t131;
            let __t134 = __t23 * __t132;
            let __t136 = __t73 * __t134;
            let __t138 = __v2 * __t52;
            let __t140 = __t136 + __t138;
            let __t142 = __t18 * __t43;
            let __t143 = __t22 * __t132;
            let __t145 = __t142 - __t143;
            let __t146 = __t69 * __t145;
            let __t147 = __t146 - __t140;
            let __t148 = __t24 * __t132;
            let __t150 = __t77 * __t148;
            let __t152 = __v1 * __t57;
            let __t153 = __t152 - __t150;
            let __t154 = __t147 + __t153;
            let __t155 = __t82 * __t154;
            let __t157 = __v16 * __t155;
            let __t159 = __t157 - __t128;
            let __t160 = __t52 * __t87;
            let __t162 = __t50 * __t131;
            let __t164 = __t19 * __t43;
            let __t165 = __t23 * __t162;
            let __t167 = __t164 - __t165;
            let __t168 = __t73 * __t167;
            let __t169 = __t22 * __t162;
            let __t171 = __t69 * __t169;
            let __t173 = __v2 * __t47;
            let __t174 = __t173 - __t171;
            let __t175 = __t168 + __t174;
            let __t177 = __t24 * __t162;
            let __t179 = __t77 * __t177;
            let __t181 = __v0 * __t57;
            let __t183 = __t179 + __t181;
            let __t185 = __t175 - __t183;
            let __t186 = __t82 * __t185;
            let __t188 = __v16 * __t186;
            let __t190 = __t188 - __t160;
            let __t191 = __t57 * __t87;
            let __t193 = __t55 * __t131;
            let __t195 = __t23 * __t193;
            let __t197 = __t73 * __t195;
            let __t199 = __v0 * __t52;
            let __t200 = __t199 - __t197;
            let __t202 = __t22 * __t193;
            let __t204 = __t69 * __t202;
            let __t206 = __v1 * __t47;
            let __t208 = __t204 + __t206;
            let __t210 = __t200 - __t208;
            let __t211 = __t20 * __t43;
            let __t212 = __t24 * __t193;
            let __t214 = __t211 - __t212;
            let __t215 = __t77 * __t214;
            let __t216 = __t210 + __t215;
            let __t217 = __t82 * __t216;
            let __t219 = __v16 * __t217;
            let __t221 = __t219 - __t191;
            let __t222 = __t95 * __t95;
            let __t223 = __v16 * __t222;
            let __t224 = __v7 + __t223;
            let __t225 = __t95 * __t108;
            let __t226 = __v16 * __t225;
            let __t227 = __t95 * __t120;
            let __t228 = __v16 * __t227;
            let __t229 = __t108 * __t108;
            let __t230 = __v16 * __t229;
            let __t231 = __v8 + __t230;
            let __t232 = __t108 * __t120;
            let __t233 = __v16 * __t232;
            let __t234 = __t120 * __t120;
            let __t235 = __v16 * __t234;
            let __t236 = __v9 + __t235;
            let __t237 = __v4 * __t148;
            let __t239 = __v5 * __t134;
            let __t241 = __t237 - __t239;
            let __t242 = __t95 * __t154;
            let __t243 = __t82 * __t241;
            let __t244 = __t242 + __t243;
            let __t245 = __v16 * __t244;
            let __t246 = __v4 * __t177;
            let __t248 = __t57 - __t246;
            let __t250 = __v5 * __t167;
            let __t251 = __t250 - __t248;
            let __t252 = __t95 * __t185;
            let __t253 = __t82 * __t251;
            let __t254 = __t252 + __t253;
            let __t255 = __v16 * __t254;
            let __t256 = __v4 * __t214;
            let __t258 = __v5 * __t195;
            let __t260 = __t52 - __t258;
            let __t261 = __t260 - __t256;
            let __t262 = __t95 * __t216;
            let __t263 = __t82 * __t261;
            let __t264 = __t262 + __t263;
            let __t265 = __v16 * __t264;
            let __t266 = __v3 * __t148;
            let __t268 = __t57 - __t266;
            let __t269 = __v5 * __t145;
            let __t271 = __t268 - __t269;
            let __t272 = __t108 * __t154;
            let __t273 = __t82 * __t271;
            let __t274 = __t272 + __t273;
            let __t275 = __v16 * __t274;
            let __t276 = __v3 * __t177;
            let __t278 = __v5 * __t169;
            let __t280 = __t278 - __t276;
            let __t281 = __t108 * __t185;
            let __t282 = __t82 * __t280;
            let __t283 = __t281 + __t282;
            let __t284 = __v16 * __t283;
            let __t285 = __v3 * __t214;
            let __t286 = __v5 * __t202;
            let __t288 = __t47 - __t286;
            let __t290 = __t285 - __t288;
            let __t291 = __t108 * __t216;
            let __t292 = __t82 * __t290;
            let __t293 = __t291 + __t292;
            let __t294 = __v16 * __t293;
            let __t295 = __v4 * __t145;
            let __t296 = __v3 * __t134;
            let __t298 = __t52 - __t296;
            let __t300 = __t295 - __t298;
            let __t301 = __t120 * __t154;
            let __t302 = __t82 * __t300;
            let __t303 = __t301 + __t302;
            let __t304 = __v16 * __t303;
            let __t305 = __v4 * __t169;
            let __t307 = __t47 - __t305;
            let __t308 = __v3 * __t167;
            let __t310 = __t307 - __t308;
            let __t311 = __t120 * __t185;
            let __t312 = __t82 * __t310;
            let __t313 = __t311 + __t312;
            let __t314 = __v16 * __t313;
            let __t315 = __v4 * __t202;
            let __t317 = __v3 * __t195;
            let __t319 = __t317 - __t315;
            let __t320 = __t120 * __t216;
            let __t321 = __t82 * __t319;
            let __t322 = __t320 + __t321;
            let __t323 = __v16 * __t322;
            let __t1879 = __t69 * __t245;
            let __t1880 = __t73 * __t255;
            let __t1881 = __t77 * __t265;
            let __t1882 = __t1879 + __t1880;
            let __t1883 = __t1881 + __t1882;
            let __t1884 = __t69 * __t275;
            let __t1885 = __t73 * __t284;
            let __t1886 = __t77 * __t294;
            let __t1887 = __t1884 + __t1885;
            let __t1888 = __t1886 + __t1887;
            let __t1889 = __t69 * __t304;
            let __t1890 = __t73 * __t314;
            let __t1891 = __t77 * __t323;
            let __t1892 = __t1889 + __t1890;
            let __t1893 = __t1891 + __t1892;
            let __t1894 = __v2 * __t115;
            let __t1895 = __v1 * __t127;
            let __t1897 = __t1894 - __t1895;
            let __t1898 = __v0 * __t127;
            let __t1899 = __v2 * __t103;
            let __t1901 = __t1898 - __t1899;
            let __t1902 = __v1 * __t103;
            let __t1903 = __v0 * __t115;
            let __t1905 = __t1902 - __t1903;
            let __t1906 = __v5 * __t190;
            let __t1907 = __v4 * __t221;
            let __t1909 = __t1906 - __t1907;
            let __t1910 = __v3 * __t221;
            let __t1911 = __v5 * __t159;
            let __t1913 = __t1910 - __t1911;
            let __t1914 = __v4 * __t159;
            let __t1915 = __v3 * __t190;
            let __t1917 = __t1914 - __t1915;
            let __t1918 = __t1897 + __t1909;
            let __t1920 = __t1918 - __t1883;
            let __t1921 = __t1901 + __t1913;
            let __t1923 = __t1921 - __t1888;
            let __t1924 = __t1905 + __t1917;
            let __t1926 = __t1924 - __t1893;
            __FullEquations {
                inertia: __Matrix3::new(
                    __t224,
                    __t226,
                    __t228,
                    __t226,
                    __t231,
                    __t233,
                    __t228,
                    __t233,
                    __t236,
                ),
                right_side: __Vector3::new(__t1920, __t1923, __t1926),
                rank_one: __MaybeRankOne::Some(__RankOneInertia {
                    weight: __v16,
                    vector: __Vector3::new(__t95, __t108, __t120),
                }),
            }
        }
    }
    #[automatically_derived]
    impl ::routh::__private::Routhian for DiagonalEllipsoid {
        #[inline]
        fn psi_dot(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __F64 {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.inertia[0usize];
            let __v8: __F64 = self.inertia[1usize];
            let __v9: __F64 = self.inertia[2usize];
            let __t58 = __v0 * __v7;
            let __t59 = __v1 * __v8;
            let __t60 = __v2 * __v9;
            let __t336 = __v3 * __v7;
            let __t337 = __v4 * __v8;
            let __t338 = __v5 * __v9;
            let __t339 = __v3 * __t336;
            let __t340 = __v4 * __t337;
            let __t341 = __v5 * __t338;
            let __t342 = __t339 + __t340;
            let __t343 = __t341 + __t342;
            let __t1667 = __v4 * __t59;
            let __t1668 = __v1 * __t337;
            let __t1669 = __t1667 + __t1668;
            let __t1670 = __v3 * __t58;
            let __t1671 = __v0 * __t336;
            let __t1672 = __t1670 + __t1671;
            let __t1673 = __t1669 + __t1672;
            let __t1674 = __v5 * __t60;
            let __t1675 = __v2 * __t338;
            let __t1676 = __t1674 + __t1675;
            let __t1677 = __t1673 + __t1676;
            let __t1679 = (-0.5f64) * __t1677;
            let __t1680 = __v6 + __t1679;
            let __t1681 = __t1680 / __t343;
            __t1681
        }
        #[inline]
        fn routhian(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __F64 {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.inertia[0usize];
            let __v8: __F64 = self.inertia[1usize];
            let __v9: __F64 = self.inertia[2usize];
            let __v10: __F64 = self.semi_axes[0usize];
            let __v11: __F64 = self.semi_axes[1usize];
            let __v12: __F64 = self.semi_axes[2usize];
            let __v13: __F64 = self.offset[0usize];
            let __v14: __F64 = self.offset[1usize];
            let __v15: __F64 = self.offset[2usize];
            let __v16: __F64 = self.mass;
            let __v17: __F64 = self.g;
            let __t18 = __v10 * __v10;
            let __t19 = __v11 * __v11;
            let __t20 = __v12 * __v12;
            let __t22 = __v3 * __t18;
            let __t23 = __v4 * __t19;
            let __t24 = __v5 * __t20;
            let __t25 = __v3 * __t22;
            let __t26 = __v4 * __t23;
            let __t27 = __v5 * __t24;
            let __t28 = __t25 + __t26;
            let __t29 = __t27 + __t28;
            let __t30 = __t29.sqrt();
            let __t31 = __v3 * __v13;
            let __t32 = __v4 * __v14;
            let __t33 = __v5 * __v15;
            let __t34 = __t31 + __t32;
            let __t35 = __t33 + __t34;
            let __t37 = __t30 - __t35;
            let __t43 = 1.0f64 / __t30;
            let __t45 = __t22 * __t43;
            let __t47 = __t45 - __v13;
            let __t50 = __t23 * __t43;
            let __t52 = __t50 - __v14;
            let __t55 = __t24 * __t43;
            let __t57 = __t55 - __v15;
            let __t58 = __v0 * __v7;
            let __t59 = __v1 * __v8;
            let __t60 = __v2 * __v9;
            let __t61 = __v0 * __t58;
            let __t62 = __v1 * __t59;
            let __t63 = __v2 * __t60;
            let __t64 = __t61 + __t62;
            let __t65 = __t63 + __t64;
            let __t66 = __v2 * __v4;
            let __t67 = __v1 * __v5;
            let __t69 = __t66 - __t67;
            let __t70 = __v0 * __v5;
            let __t71 = __v2 * __v3;
            let __t73 = __t70 - __t71;
            let __t74 = __v1 * __v3;
            let __t75 = __v0 * __v4;
            let __t77 = __t74 - __t75;
            let __t78 = __t47 * __t69;
            let __t79 = __t52 * __t73;
            let __t80 = __t57 * __t77;
            let __t81 = __t78 + __t79;
            let __t82 = __t80 + __t81;
            let __t83 = __t82 * __t82;
            let __t84 = __v16 * __t83;
            let __t85 = __t65 + __t84;
            let __t86 = 0.5f64 * __t85;
            let __t87 = __v16 * __v17;
            let __t88 = __t37 * __t87;
            let __t90 = __t86 - __t88;
            let __t336 = __v3 * __v7;
            let __t337 = __v4 * __v8;
            let __t338 = __v5 * __v9;
            let __t339 = __v3 * __t336;
            let __t340 = __v4 * __t337;
            let __t341 = __v5 * __t338;
            let __t342 = __t339 + __t340;
            let __t343 = __t341 + __t342;
            let __t1667 = __v4 * __t59;
            let __t1668 = __v1 * __t337;
            let __t1669 = __t1667 + __t1668;
            let __t1670 = __v3 * __t58;
            let __t1671 = __v0 * __t336;
            let __t1672 = __t1670 + __t1671;
            let __t1673 = __t1669 + __t1672;
            let __t1674 = __v5 * __t60;
            let __t1675 = __v2 * __t338;
            let __t1676 = __t1674 + __t1675;
            let __t1677 = __t1673 + __t1676;
            let __t1679 = (-0.5f64) * __t1677;
            let __t1680 = __v6 + __t1679;
            let __t1681 = __t1680 / __t343;
            let __t1683 = __t1680 * __t1681;
            let __t1685 = (-0.5f64) * __t1683;
            let __t1686 = __t90 + __t1685;
            __t1686
        }
        #[inline]
        fn dr_domega(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __Vector3 {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.inertia[0usize];
            let __v8: __F64 = self.inertia[1usize];
            let __v9: __F64 = self.inertia[2usize];
            let __v10: __F64 = self.semi_axes[0usize];
            let __v11: __F64 = self.semi_axes[1usize];
            let __v12: __F64 = self.semi_axes[2usize];
            let __v13: __F64 = self.offset[0usize];
            let __v14: __F64 = self.offset[1usize];
            let __v15: __F64 = self.offset[2usize];
            let __v16: __F64 = self.mass;
            let __t18 = __v10 * __v10;
            let __t19 = __v11 * __v11;
            let __t20 = __v12 * __v12;
            let __t22 = __v3 * __t18;
            let __t23 = __v4 * __t19;
            let __t24 = __v5 * __t20;
            let __t25 = __v3 * __t22;
            let __t26 = __v4 * __t23;
            let __t27 = __v5 * __t24;
            let __t28 = __t25 + __t26;
            let __t29 = __t27 + __t28;
            let __t30 = __t29.sqrt();
            let __t43 = 1.0f64 / __t30;
            let __t45 = __t22 * __t43;
            let __t47 = __t45 - __v13;
            let __t50 = __t23 * __t43;
            let __t52 = __t50 - __v14;
            let __t55 = __t24 * __t43;
            let __t57 = __t55 - __v15;
            let __t58 = __v0 * __v7;
            let __t59 = __v1 * __v8;
            let __t60 = __v2 * __v9;
            let __t66 = __v2 * __v4;
            let __t67 = __v1 * __v5;
            let __t69 = __t66 - __t67;
            let __t70 = __v0 * __v5;
            let __t71 = __v2 * __v3;
            let __t73 = __t70 - __t71;
            let __t74 = __v1 * __v3;
            let __t75 = __v0 * __v4;
            let __t77 = __t74 - __t75;
            let __t78 = __t47 * __t69;
            let __t79 = __t52 * __t73;
            let __t80 = __t57 * __t77;
            let __t81 = __t78 + __t79;
            let __t82 = __t80 + __t81;
            let __t91 = __v5 * __t52;
            let __t93 = __v4 * __t57;
            let __t95 = __t91 - __t93;
            let __t97 = __t82 * __t95;
            let __t99 = __v16 * __t97;
            let __t105 = __v5 * __t47;
            let __t107 = __v3 * __t57;
            let __t108 = __t107 - __t105;
            let __t109 = __t82 * __t108;
            let __t111 = __v16 * __t109;
            let __t117 = __v3 * __t52;
            let __t119 = __v4 * __t47;
            let __t120 = __t119 - __t117;
            let __t121 = __t82 * __t120;
            let __t123 = __v16 * __t121;
            let __t336 = __v3 * __v7;
            let __t337 = __v4 * __v8;
            let __t338 = __v5 * __v9;
            let __t339 = __v3 * __t336;
            let __t340 = __v4 * __t337;
            let __t341 = __v5 * __t338;
            let __t342 = __t339 + __t340;
            let __t343 = __t341 + __t342;
            let __t1667 = __v4 * __t59;
            let __t1668 = __v1 * __t337;
            let __t1669 = __t1667 + __t1668;
            let __t1670 = __v3 * __t58;
            let __t1671 = __v0 * __t336;
            let __t1672 = __t1670 + __t1671;
            let __t1673 = __t1669 + __t1672;
            let __t1674 = __v5 * __t60;
            let __t1675 = __v2 * __t338;
            let __t1676 = __t1674 + __t1675;
            let __t1677 = __t1673 + __t1676;
            let __t1679 = (-0.5f64) * __t1677;
            let __t1680 = __v6 + __t1679;
            let __t1681 = __t1680 / __t343;
            let __t1691 = __t336 * __t1681;
            let __t1692 = __t337 * __t1681;
            let __t1693 = __t338 * __t1681;
            let __t1694 = __t58 + __t1691;
            let __t1695 = __t59 + __t1692;
            let __t1696 = __t60 + __t1693;
            let __t1697 = __t99 + __t1694;
            let __t1698 = __t111 + __t1695;
            let __t1699 = __t123 + __t1696;
            __Vector3::new(__t1697, __t1698, __t1699)
        }
        #[inline]
        fn dr_dgamma(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __Vector3 {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.inertia[0usize];
            let __v8: __F64 = self.inertia[1usize];
            let __v9: __F64 = self.inertia[2usize];
            let __v10: __F64 = self.semi_axes[0usize];
            let __v11: __F64 = self.semi_axes[1usize];
            let __v12: __F64 = self.semi_axes[2usize];
            let __v13: __F64 = self.offset[0usize];
            let __v14: __F64 = self.offset[1usize];
            let __v15: __F64 = self.offset[2usize];
            let __v16: __F64 = self.mass;
            let __v17: __F64 = self.g;
            let __t18 = __v10 * __v10;
            let __t19 = __v11 * __v11;
            let __t20 = __v12 * __v12;
            let __t22 = __v3 * __t18;
            let __t23 = __v4 * __t19;
            let __t24 = __v5 * __t20;
            let __t25 = __v3 * __t22;
            let __t26 = __v4 * __t23;
            let __t27 = __v5 * __t24;
            let __t28 = __t25 + __t26;
            let __t29 = __t27 + __t28;
            let __t30 = __t29.sqrt();
            let __t43 = 1.0f64 / __t30;
            let __t45 = __t22 * __t43;
            let __t47 = __t45 - __v13;
            let __t50 = __t23 * __t43;
            let __t52 = __t50 - __v14;
            let __t55 = __t24 * __t43;
            let __t57 = __t55 - __v15;
            let __t58 = __v0 * __v7;
            let __t59 = __v1 * __v8;
            let __t60 = __v2 * __v9;
            let __t66 = __v2 * __v4;
            let __t67 = __v1 * __v5;
            let __t69 = __t66 - __t67;
            let __t70 = __v0 * __v5;
            let __t71 = __v2 * __v3;
            let __t73 = __t70 - __t71;
            let __t74 = __v1 * __v3;
            let __t75 = __v0 * __v4;
            let __t77 = __t74 - __t75;
            let __t78 = __t47 * __t69;
            let __t79 = __t52 * __t73;
            let __t80 = __t57 * __t77;
            let __t81 = __t78 + __t79;
            let __t82 = __t80 + __t81;
            let __t87 = __v16 * __v17;
            let __t128 = __t47 * __t87;
            let __t131 = __t43 * __t43;
            let __t132 = __t45 * __t131;
            let __t134 = __t23 * __t132;
            let __t136 = __t73 * __t134;
            let __t138 = __v2 * __t52;
            let __t140 = __t136 + __t138;
            let __t142 = __t18 * __t43;
            let __t143 = __t22 * __t132;
            let __t145 = __t142 - __t143;
            let __t146 = __t69 * __t145;
            let __t147 = __t146 - __t140;
            let __t148 = __t24 * __t132;
            let __t150 = __t77 * __t148;
            let __t152 = __v1 * __t57;
            let __t153 = __t152 - __t150;
            let __t154 = __t147 + __t153;
            let __t155 = __t82 * __t154;
            let __t157 = __v16 * __t155;
            let __t159 = __t157 - __t128;
            let __t160 = __t52 * __t87;
            let __t162 = __t50 * __t131;
            let __t164 = __t19 * __t43;
            let __t165 = __t23 * __t162;
            let __t167 = __t164 - __t165;
            let __t168 = __t73 * __t167;
            let __t169 = __t22 * __t162;
            let __t171 = __t69 * __t169;
            let __t173 = __v2 * __t47;
            let __t174 = __t173 - __t171;
            let __t175 = __t168 + __t174;
            let __t177 = __t24 * __t162;
            let __t179 = __t77 * __t177;
            let __t181 = __v0 * __t57;
            let __t183 = __t179 + __t181;
            let __t185 = __t175 - __t183;
            let __t186 = __t82 * __t185;
            let __t188 = __v16 * __t186;
            let __t190 = __t188 - __t160;
            let __t191 = __t57 * __t87;
            let __t193 = __t55 * __t131;
            let __t195 = __t23 * __t193;
            let __t197 = __t73 * __t195;
            let __t199 = __v0 * __t52;
            let __t200 = __t199 - __t197;
            let __t202 = __t22 * __t193;
            let __t204 = __t69 * __t202;
            let __t206 = __v1 * __t47;
            let __t208 = __t204 + __t206;
            let __t210 = __t200 - __t208;
            let __t211 = __t20 * __t43;
            let __t212 = __t24 * __t193;
            let __t214 = __t211 - __t212;
            let __t215 = __t77 * __t214;
            let __t216 = __t210 + __t215;
            let __t217 = __t82 * __t216;
            let __t219 = __v16 * __t217;
            let __t221 = __t219 - __t191;
            let __t336 = __v3 * __v7;
            let __t337 = __v4 * __v8;
            let __t338 = __v5 * __v9;
            let __t339 = __v3 * __t336;
            let __t340 = __v4 * __t337;
            let __t341 = __v5 * __t338;
            let __t342 = __t339 + __t340;
            let __t343 = __t341 + __t342;
            let __t1667 = __v4 * __t59;
            let __t1668 = __v1 * __t337;
            let __t1669 = __t1667 + __t1668;
            let __t1670 = __v3 * __t58;
            let __t1671 = __v0 * __t336;
            let __t1672 = __t1670 + __t1671;
            let __t1673 = __t1669 + __t1672;
            let __t1674 = __v5 * __t60;
            let __t1675 = __v2 * __t338;
            let __t1676 = __t1674 + __t1675;
            let __t1677 = __t1673 + __t1676;
            let __t1679 = (-0.5f64) * __t1677;
            let __t1680 = __v6 + __t1679;
            let __t1681 = __t1680 / __t343;
            let __t1691 = __t336 * __t1681;
            let __t1692 = __t337 * __t1681;
            let __t1693 = __t338 * __t1681;
            let __t1694 = __t58 + __t1691;
            let __t1695 = __t59 + __t1692;
            let __t1696 = __t60 + __t1693;
            let __t1700 = __t1681 * __t1694;
            let __t1701 = __t159 + __t1700;
            let __t1702 = __t1681 * __t1695;
            let __t1703 = __t190 + __t1702;
            let __t1704 = __t1681 * __t1696;
            let __t1705 = __t221 + __t1704;
            __Vector3::new(__t1701, __t1703, __t1705)
        }
        #[inline]
        fn dr_dp(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __F64 {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.inertia[0usize];
            let __v8: __F64 = self.inertia[1usize];
            let __v9: __F64 = self.inertia[2usize];
            let __t58 = __v0 * __v7;
            let __t59 = __v1 * __v8;
            let __t60 = __v2 * __v9;
            let __t336 = __v3 * __v7;
            let __t337 = __v4 * __v8;
            let __t338 = __v5 * __v9;
            let __t339 = __v3 * __t336;
            let __t340 = __v4 * __t337;
            let __t341 = __v5 * __t338;
            let __t342 = __t339 + __t340;
            let __t343 = __t341 + __t342;
            let __t1667 = __v4 * __t59;
            let __t1668 = __v1 * __t337;
            let __t1669 = __t1667 + __t1668;
            let __t1670 = __v3 * __t58;
            let __t1671 = __v0 * __t336;
            let __t1672 = __t1670 + __t1671;
            let __t1673 = __t1669 + __t1672;
            let __t1674 = __v5 * __t60;
            let __t1675 = __v2 * __t338;
            let __t1676 = __t1674 + __t1675;
            let __t1677 = __t1673 + __t1676;
            let __t1679 = (-0.5f64) * __t1677;
            let __t1680 = __v6 + __t1679;
            let __t1681 = __t1680 / __t343;
            let __t1793 = -__t1681;
            __t1793
        }
        #[inline]
        fn d2r_domega2(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __Matrix3 {
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v7: __F64 = self.inertia[0usize];
            let __v8: __F64 = self.inertia[1usize];
            let __v9: __F64 = self.inertia[2usize];
            let __v10: __F64 = self.semi_axes[0usize];
            let __v11: __F64 = self.semi_axes[1usize];
            let __v12: __F64 = self.semi_axes[2usize];
            let __v13: __F64 = self.offset[0usize];
            let __v14: __F64 = self.offset[1usize];
            let __v15: __F64 = self.offset[2usize];
            let __v16: __F64 = self.mass;
            let __t18 = __v10 * __v10;
            let __t19 = __v11 * __v11;
            let __t20 = __v12 * __v12;
            let __t22 = __v3 * __t18;
            let __t23 = __v4 * __t19;
            let __t24 = __v5 * __t20;
            let __t25 = __v3 * __t22;
            let __t26 = __v4 * __t23;
            let __t27 = __v5 * __t24;
            let __t28 = __t25 + __t26;
            let __t29 = __t27 + __t28;
            let __t30 = __t29.sqrt();
            let __t43 = 1.0f64 / __t30;
            let __t45 = __t22 * __t43;
            let __t47 = __t45 - __v13;
            let __t50 = __t23 * __t43;
            let __t52 = __t50 - __v14;
            let __t55 = __t24 * __t43;
            let __t57 = __t55 - __v15;
            let __t91 = __v5 * __t52;
            let __t93 = __v4 * __t57;
            let __t95 = __t91 - __t93;
            let __t105 = __v5 * __t47;
            let __t107 = __v3 * __t57;
            let __t108 = __t107 - __t105;
            let __t117 = __v3 * __t52;
            let __t119 = __v4 * __t47;
            let __t120 = __t119 - __t117;
            let __t222 = __t95 * __t95;
            let __t223 = __v16 * __t222;
            let __t224 = __v7 + __t223;
            let __t225 = __t95 * __t108;
            let __t226 = __v16 * __t225;
            let __t227 = __t95 * __t120;
            let __t228 = __v16 * __t227;
            let __t229 = __t108 * __t108;
            let __t230 = __v16 * __t229;
            let __t231 = __v8 + __t230;
            let __t232 = __t108 * __t120;
            let __t233 = __v16 * __t232;
            let __t234 = __t120 * __t120;
            let __t235 = __v16 * __t234;
            let __t236 = __v9 + __t235;
            let __t336 = __v3 * __v7;
            let __t337 = __v4 * __v8;
            let __t338 = __v5 * __v9;
            let __t339 = __v3 * __t336;
            let __t340 = __v4 * __t337;
            let __t341 = __v5 * __t338;
            let __t342 = __t339 + __t340;
            let __t343 = __t341 + __t342;
            let __t353 = 1.0f64 / __t343;
            let __t1712 = __t336 * __t353;
            let __t1713 = __t337 * __t353;
            let __t1714 = __t338 * __t353;
            let __t1718 = __t336 * __t1712;
            let __t1720 = __t224 - __t1718;
            let __t1721 = __t337 * __t1712;
            let __t1723 = __t226 - __t1721;
            let __t1724 = __t338 * __t1712;
            let __t1726 = __t228 - __t1724;
            let __t1738 = __t337 * __t1713;
            let __t1740 = __t231 - __t1738;
            let __t1741 = __t338 * __t1713;
            let __t1743 = __t233 - __t1741;
            let __t1755 = __t338 * __t1714;
            let __t1757 = __t236 - __t1755;
            __Matrix3::new(
                __t1720,
                __t1723,
                __t1726,
                __t1723,
                __t1740,
                __t1743,
                __t1726,
                __t1743,
                __t1757,
            )
        }
        #[inline]
        fn d2r_domega_dgamma(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __Matrix3 {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.inertia[0usize];
            let __v8: __F64 = self.inertia[1usize];
            let __v9: __F64 = self.inertia[2usize];
            let __v10: __F64 = self.semi_axes[0usize];
            let __v11: __F64 = self.semi_axes[1usize];
            let __v12: __F64 = self.semi_axes[2usize];
            let __v13: __F64 = self.offset[0usize];
            let __v14: __F64 = self.offset[1usize];
            let __v15: __F64 = self.offset[2usize];
            let __v16: __F64 = self.mass;
            let __t18 = __v10 * __v10;
            let __t19 = __v11 * __v11;
            let __t20 = __v12 * __v12;
            let __t22 = __v3 * __t18;
            let __t23 = __v4 * __t19;
            let __t24 = __v5 * __t20;
            let __t25 = __v3 * __t22;
            let __t26 = __v4 * __t23;
            let __t27 = __v5 * __t24;
            let __t28 = __t25 + __t26;
            let __t29 = __t27 + __t28;
            let __t30 = __t29.sqrt();
            let __t43 = 1.0f64 / __t30;
            let __t45 = __t22 * __t43;
            let __t47 = __t45 - __v13;
            let __t50 = __t23 * __t43;
            let __t52 = __t50 - __v14;
            let __t55 = __t24 * __t43;
            let __t57 = __t55 - __v15;
            let __t58 = __v0 * __v7;
            let __t59 = __v1 * __v8;
            let __t60 = __v2 * __v9;
            let __t66 = __v2 * __v4;
            let __t67 = __v1 * __v5;
            let __t69 = __t66 - __t67;
            let __t70 = __v0 * __v5;
            let __t71 = __v2 * __v3;
            let __t73 = __t70 - __t71;
            let __t74 = __v1 * __v3;
            let __t75 = __v0 * __v4;
            let __t77 = __t74 - __t75;
            let __t78 = __t47 * __t69;
            let __t79 = __t52 * __t73;
            let __t80 = __t57 * __t77;
            let __t81 = __t78 + __t79;
            let __t82 = __t80 + __t81;
            let __t91 = __v5 * __t52;
            let __t93 = __v4 * __t57;
            let __t95 = __t91 - __t93;
            let __t105 = __v5 * __t47;
            let __t107 = __v3 * __t57;
            let __t108 = __t107 - __t105;
            let __t117 = __v3 * __t52;
            let __t119 = __v4 * __t47;
            let __t120 = __t119 - __t117;
            let __t131 = __t43 * __t43;
            let __t132 = __t45 * __t131;
            let __t134 = __t23 * __t132;
            let __t136 = __t73 * __t134;
            let __t138 = __v2 * __t52;
            let __t140 = __t136 + __t138;
            let __t142 = __t18 * __t43;
            let __t143 = __t22 * __t132;
            let __t145 = __t142 - __t143;
            let __t146 = __t69 * __t145;
            let __t147 = __t146 - __t140;
            let __t148 = __t24 * __t132;
            let __t150 = __t77 * __t148;
            let __t152 = __v1 * __t57;
            let __t153 = __t152 - __t150;
            let __t154 = __t147 + __t153;
            let __t162 = __t50 * __t131;
            let __t164 = __t19 * __t43;
            let __t165 = __t23 * __t162;
            let __t167 = __t164 - __t165;
            let __t168 = __t73 * __t167;
            let __t169 = __t22 * __t162;
            let __t171 = __t69 * __t169;
            let __t173 = __v2 * __t47;
            let __t174 = __t173 - __t171;
            let __t175 = __t168 + __t174;
            let __t177 = __t24 * __t162;
            let __t179 = __t77 * __t177;
            let __t181 = __v0 * __t57;
            let __t183 = __t179 + __t181;
            let __t185 = __t175 - __t183;
            let __t193 = __t55 * __t131;
            let __t195 = __t23 * __t193;
            let __t197 = __t73 * __t195;
            let __t199 = __v0 * __t52;
            let __t200 = __t199 - __t197;
            let __t202 = __t22 * __t193;
            let __t204 = __t69 * __t202;
            let __t206 = __v1 * __t47;
            let __t208 = __t204 + __t206;
            let __t210 = __t200 - __t208;
            let __t211 = __t20 * __t43;
            let __t212 = __t24 * __t193;
            let __t214 = __t211 - __t212;
            let __t215 = __t77 * __t214;
            let __t216 = __t210 + __t215;
            let __t237 = __v4 * __t148;
            let __t239 = __v5 * __t134;
            let __t241 = __t237 - __t239;
            let __t242 = __t95 * __t154;
            let __t243 = __t82 * __t241;
            let __t244 = __t242 + __t243;
            let __t245 = __v16 * __t244;
            let __t246 = __v4 * __t177;
            let __t248 = __t57 - __t246;
            let __t250 = __v5 * __t167;
            let __t251 = __t250 - __t248;
            let __t252 = __t95 * __t185;
            let __t253 = __t82 * __t251;
            let __t254 = __t252 + __t253;
            let __t255 = __v16 * __t254;
            let __t256 = __v4 * __t214;
            let __t258 = __v5 * __t195;
            let __t260 = __t52 - __t258;
            let __t261 = __t260 - __t256;
            let __t262 = __t95 * __t216;
            let __t263 = __t82 * __t261;
            let __t264 = __t262 + __t263;
            let __t265 = __v16 * __t264;
            let __t266 = __v3 * __t148;
            let __t268 = __t57 - __t266;
            let __t269 = __v5 * __t145;
            let __t271 = __t268 - __t269;
            let __t272 = __t108 * __t154;
            let __t273 = __t82 * __t271;
            let __t274 = __t272 + __t273;
            let __t275 = __v16 * __t274;
            let __t276 = __v3 * __t177;
            let __t278 = __v5 * __t169;
            let __t280 = __t278 - __t276;
            let __t281 = __t108 * __t185;
            let __t282 = __t82 * __t280;
            let __t283 = __t281 + __t282;
            let __t284 = __v16 * __t283;
            let __t285 = __v3 * __t214;
            let __t286 = __v5 * __t202;
            let __t288 = __t47 - __t286;
            let __t290 = __t285 - __t288;
            let __t291 = __t108 * __t216;
            let __t292 = __t82 * __t290;
            let __t293 = __t291 + __t292;
            let __t294 = __v16 * __t293;
            let __t295 = __v4 * __t145;
            let __t296 = __v3 * __t134;
            let __t298 = __t52 - __t296;
            let __t300 = __t295 - __t298;
            let __t301 = __t120 * __t154;
            let __t302 = __t82 * __t300;
            let __t303 = __t301 + __t302;
            let __t304 = __v16 * __t303;
            let __t305 = __v4 * __t169;
            let __t307 = __t47 - __t305;
            let __t308 = __v3 * __t167;
            let __t310 = __t307 - __t308;
            let __t311 = __t120 * __t185;
            let __t312 = __t82 * __t310;
            let __t313 = __t311 + __t312;
            let __t314 = __v16 * __t313;
            let __t315 = __v4 * __t202;
            let __t317 = __v3 * __t195;
            let __t319 = __t317 - __t315;
            let __t320 = __t120 * __t216;
            let __t321 = __t82 * __t319;
            let __t322 = __t320 + __t321;
            let __t323 = __v16 * __t322;
            let __t336 = __v3 * __v7;
            let __t337 = __v4 * __v8;
            let __t338 = __v5 * __v9;
            let __t339 = __v3 * __t336;
            let __t340 = __v4 * __t337;
            let __t341 = __v5 * __t338;
            let __t342 = __t339 + __t340;
            let __t343 = __t341 + __t342;
            let __t353 = 1.0f64 / __t343;
            let __t398 = 2f64 * __t336;
            let __t399 = 2f64 * __t337;
            let __t400 = 2f64 * __t338;
            let __t1667 = __v4 * __t59;
            let __t1668 = __v1 * __t337;
            let __t1669 = __t1667 + __t1668;
            let __t1670 = __v3 * __t58;
            let __t1671 = __v0 * __t336;
            let __t1672 = __t1670 + __t1671;
            let __t1673 = __t1669 + __t1672;
            let __t1674 = __v5 * __t60;
            let __t1675 = __v2 * __t338;
            let __t1676 = __t1674 + __t1675;
            let __t1677 = __t1673 + __t1676;
            let __t1679 = (-0.5f64) * __t1677;
            let __t1680 = __v6 + __t1679;
            let __t1681 = __t353 * __t1680;
            let __t1706 = __t398 * __t1681;
            let __t1707 = __t58 + __t1706;
            let __t1708 = __t399 * __t1681;
            let __t1709 = __t59 + __t1708;
            let __t1710 = __t400 * __t1681;
            let __t1711 = __t60 + __t1710;
            let __t1712 = __t336 * __t353;
            let __t1713 = __t337 * __t353;
            let __t1714 = __t338 * __t353;
            let __t1727 = __v7 * __t1681;
            let __t1728 = __t245 + __t1727;
            let __t1729 = __t1707 * __t1712;
            let __t1731 = __t1728 - __t1729;
            let __t1732 = __t1709 * __t1712;
            let __t1734 = __t255 - __t1732;
            let __t1735 = __t1711 * __t1712;
            let __t1737 = __t265 - __t1735;
            let __t1744 = __t1707 * __t1713;
            let __t1746 = __t275 - __t1744;
            let __t1747 = __v8 * __t1681;
            let __t1748 = __t284 + __t1747;
            let __t1749 = __t1709 * __t1713;
            let __t1751 = __t1748 - __t1749;
            let __t1752 = __t1711 * __t1713;
            let __t1754 = __t294 - __t1752;
            let __t1758 = __t1707 * __t1714;
            let __t1760 = __t304 - __t1758;
            let __t1761 = __t1709 * __t1714;
            let __t1763 = __t314 - __t1761;
            let __t1764 = __v9 * __t1681;
            let __t1765 = __t323 + __t1764;
            let __t1766 = __t1711 * __t1714;
            let __t1768 = __t1765 - __t1766;
            __Matrix3::new(
                __t1731,
                __t1734,
                __t1737,
                __t1746,
                __t1751,
                __t1754,
                __t1760,
                __t1763,
                __t1768,
            )
        }
        #[inline]
        fn d2r_dgamma2(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __Matrix3 {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.inertia[0usize];
            let __v8: __F64 = self.inertia[1usize];
            let __v9: __F64 = self.inertia[2usize];
            let __v10: __F64 = self.semi_axes[0usize];
            let __v11: __F64 = self.semi_axes[1usize];
            let __v12: __F64 = self.semi_axes[2usize];
            let __v13: __F64 = self.offset[0usize];
            let __v14: __F64 = self.offset[1usize];
            let __v15: __F64 = self.offset[2usize];
            let __v16: __F64 = self.mass;
            let __v17: __F64 = self.g;
            let __t18 = __v10 * __v10;
            let __t19 = __v11 * __v11;
            let __t20 = __v12 * __v12;
            let __t22 = __v3 * __t18;
            let __t23 = __v4 * __t19;
            let __t24 = __v5 * __t20;
            let __t25 = __v3 * __t22;
            let __t26 = __v4 * __t23;
            let __t27 = __v5 * __t24;
            let __t28 = __t25 + __t26;
            let __t29 = __t27 + __t28;
            let __t30 = __t29.sqrt();
            let __t43 = 1.0f64 / __t30;
            let __t45 = __t22 * __t43;
            let __t47 = __t45 - __v13;
            let __t50 = __t23 * __t43;
            let __t52 = __t50 - __v14;
            let __t55 = __t24 * __t43;
            let __t57 = __t55 - __v15;
            let __t58 = __v0 * __v7;
            let __t59 = __v1 * __v8;
            let __t60 = __v2 * __v9;
            let __t66 = __v2 * __v4;
            let __t67 = __v1 * __v5;
            let __t69 = __t66 - __t67;
            let __t70 = __v0 * __v5;
            let __t71 = __v2 * __v3;
            let __t73 = __t70 - __t71;
            let __t74 = __v1 * __v3;
            let __t75 = __v0 * __v4;
            let __t77 = __t74 - __t75;
            let __t78 = __t47 * __t69;
            let __t79 = __t52 * __t73;
            let __t80 = __t57 * __t77;
            let __t81 = __t78 + __t79;
            let __t82 = __t80 + __t81;
            let __t87 = __v16 * __v17;
            let __t131 = __t43 * __t43;
            let __t132 = __t45 * __t131;
            let __t134 = __t23 * __t132;
            let __t136 = __t73 * __t134;
            let __t138 = __v2 * __t52;
            let __t140 = __t136 + __t138;
            let __t142 = __t18 * __t43;
            let __t143 = __t22 * __t132;
            let __t145 = __t142 - __t143;
            let __t146 = __t69 * __t145;
            let __t147 = __t146 - __t140;
            let __t148 = __t24 * __t132;
            let __t150 = __t77 * __t148;
            let __t152 = __v1 * __t57;
            let __t153 = __t152 - __t150;
            let __t154 = __t147 + __t153;
            let __t162 = __t50 * __t131;
            let __t164 = __t19 * __t43;
            let __t165 = __t23 * __t162;
            let __t167 = __t164 - __t165;
            let __t168 = __t73 * __t167;
            let __t169 = __t22 * __t162;
            let __t171 = __t69 * __t169;
            let __t173 = __v2 * __t47;
            let __t174 = __t173 - __t171;
            let __t175 = __t168 + __t174;
            let __t177 = __t24 * __t162;
            let __t179 = __t77 * __t177;
            let __t181 = __v0 * __t57;
            let __t183 = __t179 + __t181;
            let __t185 = __t175 - __t183;
            let __t193 = __t55 * __t131;
            let __t195 = __t23 * __t193;
            let __t197 = __t73 * __t195;
            let __t199 = __v0 * __t52;
            let __t200 = __t199 - __t197;
            let __t202 = __t22 * __t193;
            let __t204 = __t69 * __t202;
            let __t206 = __v1 * __t47;
            let __t208 = __t204 + __t206;
            let __t210 = __t200 - __t208;
            let __t211 = __t20 * __t43;
            let __t212 = __t24 * __t193;
            let __t214 = __t211 - __t212;
            let __t215 = __t77 * __t214;
            let __t216 = __t210 + __t215;
            let __t336 = __v3 * __v7;
            let __t337 = __v4 * __v8;
            let __t338 = __v5 * __v9;
            let __t339 = __v3 * __t336;
            let __t340 = __v4 * __t337;
            let __t341 = __v5 * __t338;
            let __t342 = __t339 + __t340;
            let __t343 = __t341 + __t342;
            let __t353 = 1.0f64 / __t343;
            let __t398 = 2f64 * __t336;
            let __t399 = 2f64 * __t337;
            let __t400 = 2f64 * __t338;
            let __t632 = __v1 * __t148;
            let __t635 = __t43 * __t132;
            let __t639 = __t131 * __t145;
            let __t640 = __t45 * __t635;
            let __t641 = (-2f64) * __t640;
            let __t642 = __t639 + __t641;
            let __t643 = __t24 * __t642;
            let __t644 = __t77 * __t643;
            let __t647 = 2f64 * __t632;
            let __t648 = __t644 + __t647;
            let __t650 = __t18 * __t132;
            let __t651 = __t22 * __t642;
            let __t655 = 2f64 * __t650;
            let __t656 = __t651 + __t655;
            let __t658 = __t69 * __t656;
            let __t660 = __v2 * __t134;
            let __t662 = __t23 * __t642;
            let __t663 = __t73 * __t662;
            let __t665 = (-2f64) * __t660;
            let __t666 = __t663 + __t665;
            let __t668 = __t658 + __t666;
            let __t670 = __t648 + __t668;
            let __t672 = __t154 * __t154;
            let __t673 = __t82 * __t670;
            let __t675 = __t672 - __t673;
            let __t676 = __v16 * __t675;
            let __t677 = __t87 * __t145;
            let __t679 = __t676 - __t677;
            let __t740 = __v1 * __t177;
            let __t742 = __t43 * __t162;
            let __t745 = __t131 * __t169;
            let __t747 = __t45 * __t742;
            let __t748 = (-2f64) * __t747;
            let __t749 = __t748 - __t745;
            let __t750 = __t24 * __t749;
            let __t751 = __v0 * __t148;
            let __t753 = __t77 * __t750;
            let __t754 = __t753 - __t751;
            let __t756 = __t740 + __t754;
            let __t758 = __t22 * __t749;
            let __t760 = __t18 * __t162;
            let __t762 = __t758 + __t760;
            let __t764 = __v2 * __t145;
            let __t765 = __t69 * __t762;
            let __t767 = __t764 - __t765;
            let __t768 = __v2 * __t167;
            let __t769 = __t19 * __t132;
            let __t770 = __t23 * __t749;
            let __t771 = __t769 + __t770;
            let __t772 = __t73 * __t771;
            let __t773 = __t768 + __t772;
            let __t775 = __t767 - __t773;
            let __t776 = __t775 - __t756;
            let __t777 = __t154 * __t185;
            let __t778 = __t82 * __t776;
            let __t779 = __t777 + __t778;
            let __t780 = __v16 * __t779;
            let __t781 = __t87 * __t169;
            let __t783 = __t780 + __t781;
            let __t840 = __v1 * __t214;
            let __t841 = __t43 * __t193;
            let __t844 = __t131 * __t202;
            let __t846 = __t45 * __t841;
            let __t847 = (-2f64) * __t846;
            let __t848 = __t847 - __t844;
            let __t849 = __t20 * __t132;
            let __t850 = __t24 * __t848;
            let __t851 = __t849 + __t850;
            let __t852 = __t77 * __t851;
            let __t854 = __t840 - __t852;
            let __t855 = __t22 * __t848;
            let __t857 = __t18 * __t193;
            let __t859 = __t855 + __t857;
            let __t861 = __v1 * __t145;
            let __t863 = __t69 * __t859;
            let __t865 = __t861 + __t863;
            let __t867 = __v2 * __t195;
            let __t869 = __t23 * __t848;
            let __t870 = __v0 * __t134;
            let __t871 = __t73 * __t869;
            let __t872 = __t870 + __t871;
            let __t873 = __t872 - __t867;
            let __t875 = __t865 + __t873;
            let __t877 = __t854 - __t875;
            let __t878 = __t154 * __t216;
            let __t879 = __t82 * __t877;
            let __t880 = __t878 + __t879;
            let __t881 = __v16 * __t880;
            let __t882 = __t87 * __t202;
            let __t884 = __t881 + __t882;
            let __t941 = __v0 * __t177;
            let __t943 = __t131 * __t167;
            let __t944 = __t50 * __t742;
            let __t945 = (-2f64) * __t944;
            let __t946 = __t943 + __t945;
            let __t947 = __t24 * __t946;
            let __t948 = __t77 * __t947;
            let __t950 = (-2f64) * __t941;
            let __t951 = __t948 + __t950;
            let __t953 = __v2 * __t169;
            let __t955 = __t22 * __t946;
            let __t956 = __t69 * __t955;
            let __t959 = 2f64 * __t953;
            let __t960 = __t956 + __t959;
            let __t962 = __t19 * __t162;
            let __t963 = __t23 * __t946;
            let __t967 = 2f64 * __t962;
            let __t968 = __t963 + __t967;
            let __t970 = __t73 * __t968;
            let __t972 = __t960 + __t970;
            let __t974 = __t951 + __t972;
            let __t976 = __t185 * __t185;
            let __t977 = __t82 * __t974;
            let __t979 = __t976 - __t977;
            let __t980 = __v16 * __t979;
            let __t981 = __t87 * __t167;
            let __t983 = __t980 - __t981;
            let __t1044 = __v0 * __t214;
            let __t1045 = __t131 * __t195;
            let __t1047 = __t50 * __t841;
            let __t1048 = (-2f64) * __t1047;
            let __t1049 = __t1048 - __t1045;
            let __t1050 = __t20 * __t162;
            let __t1051 = __t24 * __t1049;
            let __t1052 = __t1050 + __t1051;
            let __t1053 = __t77 * __t1052;
            let __t1054 = __t1044 + __t1053;
            let __t1056 = __v2 * __t202;
            let __t1058 = __t22 * __t1049;
            let __t1059 = __v1 * __t169;
            let __t1061 = __t69 * __t1058;
            let __t1062 = __t1061 - __t1059;
            let __t1064 = __t1056 + __t1062;
            let __t1066 = __t23 * __t1049;
            let __t1068 = __t19 * __t193;
            let __t1070 = __t1066 + __t1068;
            let __t1072 = __v0 * __t167;
            let __t1073 = __t73 * __t1070;
            let __t1075 = __t1072 - __t1073;
            let __t1076 = __t1075 - __t1064;
            let __t1077 = __t1076 - __t1054;
            let __t1078 = __t185 * __t216;
            let __t1079 = __t82 * __t1077;
            let __t1080 = __t1078 + __t1079;
            let __t1081 = __v16 * __t1080;
            let __t1082 = __t87 * __t195;
            let __t1084 = __t1081 + __t1082;
            let __t1141 = __t131 * __t214;
            let __t1142 = __t55 * __t841;
            let __t1143 = (-2f64) * __t1142;
            let __t1144 = __t1141 + __t1143;
            let __t1145 = __t20 * __t193;
            let __t1146 = __t24 * __t1144;
            let __t1150 = 2f64 * __t1145;
            let __t1151 = __t1146 + __t1150;
            let __t1153 = __t77 * __t1151;
            let __t1155 = __v1 * __t202;
            let __t1157 = __t22 * __t1144;
            let __t1158 = __t69 * __t1157;
            let __t1160 = (-2f64) * __t1155;
            let __t1161 = __t1158 + __t1160;
            let __t1163 = __v0 * __t195;
            let __t1165 = __t23 * __t1144;
            let __t1166 = __t73 * __t1165;
            let __t1169 = 2f64 * __t1163;
            let __t1170 = __t1166 + __t1169;
            let __t1172 = __t1161 + __t1170;
            let __t1174 = __t1153 + __t1172;
            let __t1176 = __t216 * __t216;
            let __t1177 = __t82 * __t1174;
            let __t1179 = __t1176 - __t1177;
            let __t1180 = __v16 * __t1179;
            let __t1181 = __t87 * __t214;
            let __t1183 = __t1180 - __t1181;
            let __t1667 = __v4 * __t59;
            let __t1668 = __v1 * __t337;
            let __t1669 = __t1667 + __t1668;
            let __t1670 = __v3 * __t58;
            let __t1671 = __v0 * __t336;
            let __t1672 = __t1670 + __t1671;
            let __t1673 = __t1669 + __t1672;
            let __t1674 = __v5 * __t60;
            let __t1675 = __v2 * __t338;
            let __t1676 = __t1674 + __t1675;
            let __t1677 = __t1673 + __t1676;
            let __t1679 = (-0.5f64) * __t1677;
            let __t1680 = __v6 + __t1679;
            let __t1681 = __t353 * __t1680;
            let __t1706 = __t398 * __t1681;
            let __t1707 = __t58 + __t1706;
            let __t1708 = __t399 * __t1681;
            let __t1709 = __t59 + __t1708;
            let __t1710 = __t400 * __t1681;
            let __t1711 = __t60 + __t1710;
            let __t1715 = __t353 * __t1707;
            let __t1716 = __t353 * __t1709;
            let __t1717 = __t353 * __t1711;
            let __t1727 = __v7 * __t1681;
            let __t1747 = __v8 * __t1681;
            let __t1764 = __v9 * __t1681;
            let __t1769 = __t1681 * __t1727;
            let __t1770 = __t679 + __t1769;
            let __t1771 = __t1707 * __t1715;
            let __t1773 = __t1770 - __t1771;
            let __t1774 = __t1709 * __t1715;
            let __t1776 = __t783 - __t1774;
            let __t1777 = __t1711 * __t1715;
            let __t1779 = __t884 - __t1777;
            let __t1780 = __t1681 * __t1747;
            let __t1781 = __t983 + __t1780;
            let __t1782 = __t1709 * __t1716;
            let __t1784 = __t1781 - __t1782;
            let __t1785 = __t1711 * __t1716;
            let __t1787 = __t1084 - __t1785;
            let __t1788 = __t1681 * __t1764;
            let __t1789 = __t1183 + __t1788;
            let __t1790 = __t1711 * __t1717;
            let __t1792 = __t1789 - __t1790;
            __Matrix3::new(
                __t1773,
                __t1776,
                __t1779,
                __t1776,
                __t1784,
                __t1787,
                __t1779,
                __t1787,
                __t1792,
            )
        }
        #[inline]
        fn amended_potential(&self, __gamma: &__Vector3, __p_psi: __F64) -> __F64 {
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.inertia[0usize];
            let __v8: __F64 = self.inertia[1usize];
            let __v9: __F64 = self.inertia[2usize];
            let __v10: __F64 = self.semi_axes[0usize];
            let __v11: __F64 = self.semi_axes[1usize];
            let __v12: __F64 = self.semi_axes[2usize];
            let __v13: __F64 = self.offset[0usize];
            let __v14: __F64 = self.offset[1usize];
            let __v15: __F64 = self.offset[2usize];
            let __v16: __F64 = self.mass;
            let __v17: __F64 = self.g;
            let __t18 = __v10 * __v10;
            let __t19 = __v11 * __v11;
            let __t20 = __v12 * __v12;
            let __t22 = __v3 * __t18;
            let __t23 = __v4 * __t19;
            let __t24 = __v5 * __t20;
            let __t25 = __v3 * __t22;
            let __t26 = __v4 * __t23;
            let __t27 = __v5 * __t24;
            let __t28 = __t25 + __t26;
            let __t29 = __t27 + __t28;
            let __t30 = __t29.sqrt();
            let __t31 = __v3 * __v13;
            let __t32 = __v4 * __v14;
            let __t33 = __v5 * __v15;
            let __t34 = __t31 + __t32;
            let __t35 = __t33 + __t34;
            let __t37 = __t30 - __t35;
            let __t87 = __v16 * __v17;
            let __t88 = __t37 * __t87;
            let __t336 = __v3 * __v7;
            let __t337 = __v4 * __v8;
            let __t338 = __v5 * __v9;
            let __t339 = __v3 * __t336;
            let __t340 = __v4 * __t337;
            let __t341 = __v5 * __t338;
            let __t342 = __t339 + __t340;
            let __t343 = __t341 + __t342;
            let __t1245 = __v6 / __t343;
            let __t1247 = __v6 * __t1245;
            let __t1249 = (-0.5f64) * __t1247;
            let __t1250 = __t1249 - __t88;
            let __t1395 = -__t1250;
            __t1395
        }
        #[inline]
        fn bundle(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __RouthBundle {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.inertia[0usize];
            let __v8: __F64 = self.inertia[1usize];
            let __v9: __F64 = self.inertia[2usize];
            let __v10: __F64 = self.semi_axes[0usize];
            let __v11: __F64 = self.semi_axes[1usize];
            let __v12: __F64 = self.semi_axes[2usize];
            let __v13: __F64 = self.offset[0usize];
            let __v14: __F64 = self.offset[1usize];
            let __v15: __F64 = self.offset[2usize];
            let __v16: __F64 = self.mass;
            let __v17: __F64 = self.g;
            let __t18 = __v10 * __v10;
            let __t19 = __v11 * __v11;
            let __t20 = __v12 * __v12;
            let __t22 = __v3 * __t18;
            let __t23 = __v4 * __t19;
            let __t24 = __v5 * __t20;
            let __t25 = __v3 * __t22;
            let __t26 = __v4 * __t23;
            let __t27 = __v5 * __t24;
            let __t28 = __t25 + __t26;
            let __t29 = __t27 + __t28;
            let __t30 = __t29.sqrt();
            let __t31 = __v3 * __v13;
            let __t32 = __v4 * __v14;
            let __t33 = __v5 * __v15;
            let __t34 = __t31 + __t32;
            let __t35 = __t33 + __t34;
            let __t37 = __t30 - __t35;
            let __t43 = 1.0f64 / __t30;
            let __t45 = __t22 * __t43;
            let __t47 = __t45 - __v13;
            let __t50 = __t23 * __t43;
            let __t52 = __t50 - __v14;
            let __t55 = __t24 * __t43;
            let __t57 = __t55 - __v15;
            let __t58 = __v0 * __v7;
            let __t59 = __v1 * __v8;
            let __t60 = __v2 * __v9;
            let __t61 = __v0 * __t58;
            let __t62 = __v1 * __t59;
            let __t63 = __v2 * __t60;
            let __t64 = __t61 + __t62;
            let __t65 = __t63 + __t64;
            let __t66 = __v2 * __v4;
            let __t67 = __v1 * __v5;
            let __t69 = __t66 - __t67;
            let __t70 = __v0 * __v5;
            let __t71 = __v2 * __v3;
            let __t73 = __t70 - __t71;
            let __t74 = __v1 * __v3;
            let __t75 = __v0 * __v4;
            let __t77 = __t74 - __t75;
            let __t78 = __t47 * __t69;
            let __t79 = __t52 * __t73;
            let __t80 = __t57 * __t77;
            let __t81 = __t78 + __t79;
            let __t82 = __t80 + __t81;
            let __t83 = __t82 * __t82;
            let __t84 = __v16 * __t83;
            let __t85 = __t65 + __t84;
            let __t86 = 0.5f64 * __t85;
            let __t87 = __v16 * __v17;
            let __t88 = __t37 * __t87;
            let __t90 = __t86 - __t88;
            let __t91 = __v5 * __t52;
            let __t93 = __v4 * __t57;
            let __t95 = __t91 - __t93;
            let __t97 = __t82 * __t95;
            let __t99 = __v16 * __t97;
            let __t105 = __v5 * __t47;
            let __t107 = __v3 * __t57;
            let __t108 = __t107 - __t105;
            let __t109 = __t82 * __t108;
            let __t111 = __v16 * __t109;
            let __t117 = __v3 * __t52;
            let __t119 = __v4 * __t47;
            let __t120 = __t119 - __t117;
            let __t121 = __t82 * __t120;
            let __t123 = __v16 * __t121;
            let __t128 = __t47 * __t87;
            let __t131 = __t43 * __t43;
            let __t132 = __t45 * __t131;
            let __t134 = __t23 * __t132;
            let __t136 = __t73 * __t134;
            let __t138 = __v2 * __t52;
            let __t140 = __t136 + __t138;
            let __t142 = __t18 * __t43;
            let __t143 = __t22 * __t132;
            let __t145 = __t142 - __t143;
            let __t146 = __t69 * __t145;
            let __t147 = __t146 - __t140;
            let __t148 = __t24 * __t132;
            let __t150 = __t77 * __t148;
            let __t152 = __v1 * __t57;
            let __t153 = __t152 - __t150;
            let __t154 = __t147 + __t153;
            let __t155 = __t82 * __t154;
            let __t157 = __v16 * __t155;
            let __t159 = __t157 - __t128;
            let __t160 = __t52 * __t87;
            let __t162 = __t50 * __t131;
            let __t164 = __t19 * __t43;
            let __t165 = __t23 * __t162;
            let __t167 = __t164 - __t165;
            let __t168 = __t73 * __t167;
            let __t169 = __t22 * __t162;
            let __t171 = __t69 * __t169;
            let __t173 = __v2 * __t47;
            let __t174 = __t173 - __t171;
            let __t175 = __t168 + __t174;
            let __t177 = __t24 * __t162;
            let __t179 = __t77 * __t177;
            let __t181 = __v0 * __t57;
            let __t183 = __t179 + __t181;
            let __t185 = __t175 - __t183;
            let __t186 = __t82 * __t185;
            let __t188 = __v16 * __t186;
            let __t190 = __t188 - __t160;
            let __t191 = __t57 * __t87;
            let __t193 = __t55 * __t131;
            let __t195 = __t23 * __t193;
            let __t197 = __t73 * __t195;
            let __t199 = __v0 * __t52;
            let __t200 = __t199 - __t197;
            let __t202 = __t22 * __t193;
            let __t204 = __t69 * __t202;
            let __t206 = __v1 * __t47;
            let __t208 = __t204 + __t206;
            let __t210 = __t200 - __t208;
            let __t211 = __t20 * __t43;
            let __t212 = __t24 * __t193;
            let __t214 = __t211 - __t212;
            let __t215 = __t77 * __t214;
            let __t216 = __t210 + __t215;
            let __t217 = __t82 * __t216;
            let __t219 = __v16 * __t217;
            let __t221 = __t219 - __t191;
            let __t222 = __t95 * __t95;
            let __t223 = __v16 * __t222;
            let __t224 = __v7 + __t223;
            let __t225 = __t95 * __t108;
            let __t226 = __v16 * __t225;
            let __t227 = __t95 * __t120;
            let __t228 = __v16 * __t227;
            let __t229 = __t108 * __t108;
            let __t230 = __v16 * __t229;
            let __t231 = __v8 + __t230;
            let __t232 = __t108 * __t120;
            let __t233 = __v16 * __t232;
            let __t234 = __t120 * __t120;
            let __t235 = __v16 * __t234;
            let __t236 = __v9 + __t235;
            let __t237 = __v4 * __t148;
            let __t239 = __v5 * __t134;
            let __t241 = __t237 - __t239;
            let __t242 = __t95 * __t154;
            let __t243 = __t82 * __t241;
            let __t244 = __t242 + __t243;
            let __t245 = __v16 * __t244;
            let __t246 = __v4 * __t177;
            let __t248 = __t57 - __t246;
            let __t250 = __v5 * __t167;
            let __t251 = __t250 - __t248;
            let __t252 = __t95 * __t185;
            let __t253 = __t82 * __t251;
            let __t254 = __t252 + __t253;
            let __t255 = __v16 * __t254;
            let __t256 = __v4 * __t214;
            let __t258 = __v5 * __t195;
            let __t260 = __t52 - __t258;
            let __t261 = __t260 - __t256;
            let __t262 = __t95 * __t216;
            let __t263 = __t82 * __t261;
            let __t264 = __t262 + __t263;
            let __t265 = __v16 * __t264;
            let __t266 = __v3 * __t148;
            let __t268 = __t57 - __t266;
            let __t269 = __v5 * __t145;
            let __t271 = __t268 - __t269;
            let __t272 = __t108 * __t154;
            let __t273 = __t82 * __t271;
            let __t274 = __t272 + __t273;
            let __t275 = __v16 * __t274;
            let __t276 = __v3 * __t177;
            let __t278 = __v5 * __t169;
            let __t280 = __t278 - __t276;
            let __t281 = __t108 * __t185;
            let __t282 = __t82 * __t280;
            let __t283 = __t281 + __t282;
            let __t284 = __v16 * __t283;
            let __t285 = __v3 * __t214;
            let __t286 = __v5 * __t202;
            let __t288 = __t47 - __t286;
            let __t290 = __t285 - __t288;
            let __t291 = __t108 * __t216;
            let __t292 = __t82 * __t290;
            let __t293 = __t291 + __t292;
            let __t294 = __v16 * __t293;
            let __t295 = __v4 * __t145;
            let __t296 = __v3 * __t134;
            let __t298 = __t52 - __t296;
            let __t300 = __t295 - __t298;
            let __t301 = __t120 * __t154;
            let __t302 = __t82 * __t300;
            let __t303 = __t301 + __t302;
            let __t304 = __v16 * __t303;
            let __t305 = __v4 * __t169;
            let __t307 = __t47 - __t305;
            let __t308 = __v3 * __t167;
            let __t310 = __t307 - __t308;
            let __t311 = __t120 * __t185;
            let __t312 = __t82 * __t310;
            let __t313 = __t311 + __t312;
            let __t314 = __v16 * __t313;
            let __t315 = __v4 * __t202;
            let __t317 = __v3 * __t195;
            let __t319 = __t317 - __t315;
            let __t320 = __t120 * __t216;
            let __t321 = __t82 * __t319;
            let __t322 = __t320 + __t321;
            let __t323 = __v16 * __t322;
            let __t336 = __v3 * __v7;
            let __t337 = __v4 * __v8;
            let __t338 = __v5 * __v9;
            let __t339 = __v3 * __t336;
            let __t340 = __v4 * __t337;
            let __t341 = __v5 * __t338;
            let __t342 = __t339 + __t340;
            let __t343 = __t341 + __t342;
            let __t353 = 1.0f64 / __t343;
            let __t398 = 2f64 * __t336;
            let __t399 = 2f64 * __t337;
            let __t400 = 2f64 * __t338;
            let __t632 = __v1 * __t148;
            let __t635 = __t43 * __t132;
            let __t639 = __t131 * __t145;
            let __t640 = __t45 * __t635;
            let __t641 = (-2f64) * __t640;
            let __t642 = __t639 + __t641;
            let __t643 = __t24 * __t642;
            let __t644 = __t77 * __t643;
            let __t647 = 2f64 * __t632;
            let __t648 = __t644 + __t647;
            let __t650 = __t18 * __t132;
            let __t651 = __t22 * __t642;
            let __t655 = 2f64 * __t650;
            let __t656 = __t651 + __t655;
            let __t658 = __t69 * __t656;
            let __t660 = __v2 * __t134;
            let __t662 = __t23 * __t642;
            let __t663 = __t73 * __t662;
            let __t665 = (-2f64) * __t660;
            let __t666 = __t663 + __t665;
            let __t668 = __t658 + __t666;
            let __t670 = __t648 + __t668;
            let __t672 = __t154 * __t154;
            let __t673 = __t82 * __t670;
            let __t675 = __t672 - __t673;
            let __t676 = __v16 * __t675;
            let __t677 = __t87 * __t145;
            let __t679 = __t676 - __t677;
            let __t740 = __v1 * __t177;
            let __t742 = __t43 * __t162;
            let __t745 = __t131 * __t169;
            let __t747 = __t45 * __t742;
            let __t748 = (-2f64) * __t747;
            let __t749 = __t748 - __t745;
            let __t750 = __t24 * __t749;
            let __t751 = __v0 * __t148;
            let __t753 = __t77 * __t750;
            let __t754 = __t753 - __t751;
            let __t756 = __t740 + __t754;
            let __t758 = __t22 * __t749;
            let __t760 = __t18 * __t162;
            let __t762 = __t758 + __t760;
            let __t764 = __v2 * __t145;
            let __t765 = __t69 * __t762;
            let __t767 = __t764 - __t765;
            let __t768 = __v2 * __t167;
            let __t769 = __t19 * __t132;
            let __t770 = __t23 * __t749;
            let __t771 = __t769 + __t770;
            let __t772 = __t73 * __t771;
            let __t773 = __t768 + __t772;
            let __t775 = __t767 - __t773;
            let __t776 = __t775 - __t756;
            let __t777 = __t154 * __t185;
            let __t778 = __t82 * __t776;
            let __t779 = __t777 + __t778;
            let __t780 = __v16 * __t779;
            let __t781 = __t87 * __t169;
            let __t783 = __t780 + __t781;
            let __t840 = __v1 * __t214;
            let __t841 = __t43 * __t193;
            let __t844 = __t131 * __t202;
            let __t846 = __t45 * __t841;
            let __t847 = (-2f64) * __t846;
            let __t848 = __t847 - __t844;
            let __t849 = __t20 * __t132;
            let __t850 = __t24 * __t848;
            let __t851 = __t849 + __t850;
            let __t852 = __t77 * __t851;
            let __t854 = __t840 - __t852;
            let __t855 = __t22 * __t848;
            let __t857 = __t18 * __t193;
            let __t859 = __t855 + __t857;
            let __t861 = __v1 * __t145;
            let __t863 = __t69 * __t859;
            let __t865 = __t861 + __t863;
            let __t867 = __v2 * __t195;
            let __t869 = __t23 * __t848;
            let __t870 = __v0 * __t134;
            let __t871 = __t73 * __t869;
            let __t872 = __t870 + __t871;
            let __t873 = __t872 - __t867;
            let __t875 = __t865 + __t873;
            let __t877 = __t854 - __t875;
            let __t878 = __t154 * __t216;
            let __t879 = __t82 * __t877;
            let __t880 = __t878 + __t879;
            let __t881 = __v16 * __t880;
            let __t882 = __t87 * __t202;
            let __t884 = __t881 + __t882;
            let __t941 = __v0 * __t177;
            let __t943 = __t131 * __t167;
            let __t944 = __t50 * __t742;
            let __t945 = (-2f64) * __t944;
            let __t946 = __t943 + __t945;
            let __t947 = __t24 * __t946;
            let __t948 = __t77 * __t947;
            let __t950 = (-2f64) * __t941;
            let __t951 = __t948 + __t950;
            let __t953 = __v2 * __t169;
            let __t955 = __t22 * __t946;
            let __t956 = __t69 * __t955;
            let __t959 = 2f64 * __t953;
            let __t960 = __t956 + __t959;
            let __t962 = __t19 * __t162;
            let __t963 = __t23 * __t946;
            let __t967 = 2f64 * __t962;
            let __t968 = __t963 + __t967;
            let __t970 = __t73 * __t968;
            let __t972 = __t960 + __t970;
            let __t974 = __t951 + __t972;
            let __t976 = __t185 * __t185;
            let __t977 = __t82 * __t974;
            let __t979 = __t976 - __t977;
            let __t980 = __v16 * __t979;
            let __t981 = __t87 * __t167;
            let __t983 = __t980 - __t981;
            let __t1044 = __v0 * __t214;
            let __t1045 = __t131 * __t195;
            let __t1047 = __t50 * __t841;
            let __t1048 = (-2f64) * __t1047;
            let __t1049 = __t1048 - __t1045;
            let __t1050 = __t20 * __t162;
            let __t1051 = __t24 * __t1049;
            let __t1052 = __t1050 + __t1051;
            let __t1053 = __t77 * __t1052;
            let __t1054 = __t1044 + __t1053;
            let __t1056 = __v2 * __t202;
            let __t1058 = __t22 * __t1049;
            let __t1059 = __v1 * __t169;
            let __t1061 = __t69 * __t1058;
            let __t1062 = __t1061 - __t1059;
            let __t1064 = __t1056 + __t1062;
            let __t1066 = __t23 * __t1049;
            let __t1068 = __t19 * __t193;
            let __t1070 = __t1066 + __t1068;
            let __t1072 = __v0 * __t167;
            let __t1073 = __t73 * __t1070;
            let __t1075 = __t1072 - __t1073;
            let __t1076 = __t1075 - __t1064;
            let __t1077 = __t1076 - __t1054;
            let __t1078 = __t185 * __t216;
            let __t1079 = __t82 * __t1077;
            let __t1080 = __t1078 + __t1079;
            let __t1081 = __v16 * __t1080;
            let __t1082 = __t87 * __t195;
            let __t1084 = __t1081 + __t1082;
            let __t1141 = __t131 * __t214;
            let __t1142 = __t55 * __t841;
            let __t1143 = (-2f64) * __t1142;
            let __t1144 = __t1141 + __t1143;
            let __t1145 = __t20 * __t193;
            let __t1146 = __t24 * __t1144;
            let __t1150 = 2f64 * __t1145;
            let __t1151 = __t1146 + __t1150;
            let __t1153 = __t77 * __t1151;
            let __t1155 = __v1 * __t202;
            let __t1157 = __t22 * __t1144;
            let __t1158 = __t69 * __t1157;
            let __t1160 = (-2f64) * __t1155;
            let __t1161 = __t1158 + __t1160;
            let __t1163 = __v0 * __t195;
            let __t1165 = __t23 * __t1144;
            let __t1166 = __t73 * __t1165;
            let __t1169 = 2f64 * __t1163;
            let __t1170 = __t1166 + __t1169;
            let __t1172 = __t1161 + __t1170;
            let __t1174 = __t1153 + __t1172;
            let __t1176 = __t216 * __t216;
            let __t1177 = __t82 * __t1174;
            let __t1179 = __t1176 - __t1177;
            let __t1180 = __v16 * __t1179;
            let __t1181 = __t87 * __t214;
            let __t1183 = __t1180 - __t1181;
            let __t1667 = __v4 * __t59;
            let __t1668 = __v1 * __t337;
            let __t1669 = __t1667 + __t1668;
            let __t1670 = __v3 * __t58;
            let __t1671 = __v0 * __t336;
            let __t1672 = __t1670 + __t1671;
            let __t1673 = __t1669 + __t1672;
            let __t1674 = __v5 * __t60;
            let __t1675 = __v2 * __t338;
            let __t1676 = __t1674 + __t1675;
            let __t1677 = __t1673 + __t1676;
            let __t1679 = (-0.5f64) * __t1677;
            let __t1680 = __v6 + __t1679;
            let __t1681 = __t353 * __t1680;
            let __t1683 = __t1680 * __t1681;
            let __t1685 = (-0.5f64) * __t1683;
            let __t1686 = __t90 + __t1685;
            let __t1691 = __t336 * __t1681;
            let __t1692 = __t337 * __t1681;
            let __t1693 = __t338 * __t1681;
            let __t1694 = __t58 + __t1691;
            let __t1695 = __t59 + __t1692;
            let __t1696 = __t60 + __t1693;
            let __t1697 = __t99 + __t1694;
            let __t1698 = __t111 + __t1695;
            let __t1699 = __t123 + __t1696;
            let __t1700 = __t1681 * __t1694;
            let __t1701 = __t159 + __t1700;
            let __t1702 = __t1681 * __t1695;
            let __t1703 = __t190 + __t1702;
            let __t1704 = __t1681 * __t1696;
            let __t1705 = __t221 + __t1704;
            let __t1706 = __t398 * __t1681;
            let __t1707 = __t58 + __t1706;
            let __t1708 = __t399 * __t1681;
            let __t1709 = __t59 + __t1708;
            let __t1710 = __t400 * __t1681;
            let __t1711 = __t60 + __t1710;
            let __t1712 = __t336 * __t353;
            let __t1713 = __t337 * __t353;
            let __t1714 = __t338 * __t353;
            let __t1715 = __t353 * __t1707;
            let __t1716 = __t353 * __t1709;
            let __t1717 = __t353 * __t1711;
            let __t1718 = __t336 * __t1712;
            let __t1720 = __t224 - __t1718;
            let __t1721 = __t337 * __t1712;
            let __t1723 = __t226 - __t1721;
            let __t1724 = __t338 * __t1712;
            let __t1726 = __t228 - __t1724;
            let __t1727 = __v7 * __t1681;
            let __t1728 = __t245 + __t1727;
            let __t1729 = __t1707 * __t1712;
            let __t1731 = __t1728 - __t1729;
            let __t1732 = __t1709 * __t1712;
            let __t1734 = __t255 - __t1732;
            let __t1735 = __t1711 * __t1712;
            let __t1737 = __t265 - __t1735;
            let __t1738 = __t337 * __t1713;
            let __t1740 = __t231 - __t1738;
            let __t1741 = __t338 * __t1713;
            let __t1743 = __t233 - __t1741;
            let __t1744 = __t1707 * __t1713;
            let __t1746 = __t275 - __t1744;
            let __t1747 = __v8 * __t1681;
            let __t1748 = __t284 + __t1747;
            let __t1749 = __t1709 * __t1713;
            let __t1751 = __t1748 - __t1749;
            let __t1752 = __t1711 * __t1713;
            let __t1754 = __t294 - __t1752;
            let __t1755 = __t338 * __t1714;
            let __t1757 = __t236 - __t1755;
            let __t1758 = __t1707 * __t1714;
            let __t1760 = __t304 - __t1758;
            let __t1761 = __t1709 * __t1714;
            let __t1763 = __t314 - __t1761;
            let __t1764 = __v9 * __t1681;
            let __t1765 = __t323 + __t1764;
            let __t1766 = __t1711 * __t1714;
            let __t1768 = __t1765 - __t1766;
            let __t1769 = __t1681 * __t1727;
            let __t1770 = __t679 + __t1769;
            let __t1771 = __t1707 * __t1715;
            let __t1773 = __t1770 - __t1771;
            let __t1774 = __t1709 * __t1715;
            let __t1776 = __t783 - __t1774;
            let __t1777 = __t1711 * __t1715;
            let __t1779 = __t884 - __t1777;
            let __t1780 = __t1681 * __t1747;
            let __t1781 = __t983 + __t1780;
            let __t1782 = __t1709 * __t1716;
            let __t1784 = __t1781 - __t1782;
            let __t1785 = __t1711 * __t1716;
            let __t1787 = __t1084 - __t1785;
            let __t1788 = __t1681 * __t1764;
            let __t1789 = __t1183 + __t1788;
            let __t1790 = __t1711 * __t1717;
            let __t1792 = __t1789 - __t1790;
            let __t1793 = -__t1681;
            __RouthBundle {
                routhian: __t1686,
                psi_dot: __t1681,
                dr_domega: __Vector3::new(__t1697, __t1698, __t1699),
                dr_dgamma: __Vector3::new(__t1701, __t1703, __t1705),
                dr_dp: __t1793,
                d2r_domega2: __Matrix3::new(
                    __t1720,
                    __t1723,
                    __t1726,
                    __t1723,
                    __t1740,
                    __t1743,
                    __t1726,
                    __t1743,
                    __t1757,
                ),
                d2r_domega_dgamma: __Matrix3::new(
                    __t1731,
                    __t1734,
                    __t1737,
                    __t1746,
                    __t1751,
                    __t1754,
                    __t1760,
                    __t1763,
                    __t1768,
                ),
                d2r_dgamma2: __Matrix3::new(
                    __t1773,
                    __t1776,
                    __t1779,
                    __t1776,
                    __t1784,
                    __t1787,
                    __t1779,
                    __t1787,
                    __t1792,
                ),
            }
        }
        #[inline]
        fn gyroscopic_system(
            &self,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __GyroscopicSystem {
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.inertia[0usize];
            let __v8: __F64 = self.inertia[1usize];
            let __v9: __F64 = self.inertia[2usize];
            let __v10: __F64 = self.semi_axes[0usize];
            let __v11: __F64 = self.semi_axes[1usize];
            let __v12: __F64 = self.semi_axes[2usize];
            let __v13: __F64 = self.offset[0usize];
            let __v14: __F64 = self.offset[1usize];
            let __v15: __F64 = self.offset[2usize];
            let __v16: __F64 = self.mass;
            let __v17: __F64 = self.g;
            let __t18 = __v10 * __v10;
            let __t19 = __v11 * __v11;
            let __t20 = __v12 * __v12;
            let __t22 = __v3 * __t18;
            let __t23 = __v4 * __t19;
            let __t24 = __v5 * __t20;
            let __t25 = __v3 * __t22;
            let __t26 = __v4 * __t23;
            let __t27 = __v5 * __t24;
            let __t28 = __t25 + __t26;
            let __t29 = __t27 + __t28;
            let __t30 = __t29.sqrt();
            let __t43 = 1.0f64 / __t30;
            let __t45 = __t22 * __t43;
            let __t47 = __t45 - __v13;
            let __t50 = __t23 * __t43;
            let __t52 = __t50 - __v14;
            let __t55 = __t24 * __t43;
            let __t57 = __t55 - __v15;
            let __t87 = __v16 * __v17;
            let __t91 = __v5 * __t52;
            let __t93 = __v4 * __t57;
            let __t95 = __t91 - __t93;
            let __t105 = __v5 * __t47;
            let __t107 = __v3 * __t57;
            let __t108 = __t107 - __t105;
            let __t117 = __v3 * __t52;
            let __t119 = __v4 * __t47;
            let __t120 = __t119 - __t117;
            let __t128 = __t47 * __t87;
            let __t131 = __t43 * __t43;
            let __t132 = __t45 * __t131;
            let __t142 = __t18 * __t43;
            let __t143 = __t22 * __t132;
            let __t145 = __t142 - __t143;
            let __t160 = __t52 * __t87;
            let __t162 = __t50 * __t131;
            let __t164 = __t19 * __t43;
            let __t165 = __t23 * __t162;
            let __t167 = __t164 - __t165;
            let __t169 = __t22 * __t162;
            let __t191 = __t57 * __t87;
            let __t193 = __t55 * __t131;
            let __t195 = __t23 * __t193;
            let __t202 = __t22 * __t193;
            let __t211 = __t20 * __t43;
            let __t212 = __t24 * __t193;
            let __t214 = __t211 - __t212;
            let __t222 = __t95 * __t95;
            let __t223 = __v16 * __t222;
            let __t224 = __v7 + __t223;
            let __t225 = __t95 * __t108;
            let __t226 = __v16 * __t225;
            let __t227 = __t95 * __t120;
            let __t228 = __v16 * __t227;
            let __t229 = __t108 * __t108;
            let __t230 = __v16 * __t229;
            let __t231 = __v8 + __t230;
            let __t232 = __t108 * __t120;
            let __t233 = __v16 * __t232;
            let __t234 = __t120 * __t120;
            let __t235 = __v16 * __t234;
            let __t236 = __v9 + __t235;
            let __t336 = __v3 * __v7;
            let __t337 = __v4 * __v8;
            let __t338 = __v5 * __v9;
            let __t339 = __v3 * __t336;
            let __t340 = __v4 * __t337;
            let __t341 = __v5 * __t338;
            let __t342 = __t339 + __t340;
            let __t343 = __t341 + __t342;
            let __t353 = 1.0f64 / __t343;
            let __t677 = __t87 * __t145;
            let __t781 = __t87 * __t169;
            let __t882 = __t87 * __t202;
            let __t981 = __t87 * __t167;
            let __t1082 = __t87 * __t195;
            let __t1181 = __t87 * __t214;
            let __t1245 = __v6 * __t353;
            let __t1252 = __t336 * __t1245;
            let __t1253 = __t337 * __t1245;
            let __t1254 = __t338 * __t1245;
            let __t1258 = __t1245 * __t1252;
            let __t1259 = __t1258 - __t128;
            let __t1260 = __t1245 * __t1253;
            let __t1261 = __t1260 - __t160;
            let __t1262 = __t1245 * __t1254;
            let __t1263 = __t1262 - __t191;
            let __t1267 = __t353 * __t1252;
            let __t1269 = __t353 * __t1253;
            let __t1271 = __t353 * __t1254;
            let __t1330 = __v7 * __t1245;
            let __t1331 = __t1245 * __t1330;
            let __t1332 = __t1331 - __t677;
            let __t1333 = __t1252 * __t1267;
            let __t1338 = (-4f64) * __t1333;
            let __t1339 = __t1332 + __t1338;
            let __t1340 = __t1253 * __t1267;
            let __t1343 = (-4f64) * __t1340;
            let __t1344 = __t781 + __t1343;
            let __t1345 = __t1254 * __t1267;
            let __t1348 = (-4f64) * __t1345;
            let __t1349 = __t882 + __t1348;
            let __t1362 = __v8 * __t1245;
            let __t1363 = __t1245 * __t1362;
            let __t1364 = __t1363 - __t981;
            let __t1365 = __t1253 * __t1269;
            let __t1368 = (-4f64) * __t1365;
            let __t1369 = __t1364 + __t1368;
            let __t1370 = __t1254 * __t1269;
            let __t1373 = (-4f64) * __t1370;
            let __t1374 = __t1082 + __t1373;
            let __t1387 = __v9 * __t1245;
            let __t1388 = __t1245 * __t1387;
            let __t1389 = __t1388 - __t1181;
            let __t1390 = __t1254 * __t1271;
            let __t1393 = (-4f64) * __t1390;
            let __t1394 = __t1389 + __t1393;
            let __t1408 = __v3 * __t1259;
            let __t1409 = __v4 * __t1261;
            let __t1410 = __v5 * __t1263;
            let __t1411 = __t1408 + __t1409;
            let __t1412 = __t1410 + __t1411;
            let __t1414 = __t1412 - __t1339;
            let __t1418 = __t1412 - __t1369;
            let __t1421 = __t1412 - __t1394;
            let __t1422 = __v5 * __t1344;
            let __t1424 = __v4 * __t1349;
            let __t1426 = __t1424 - __t1422;
            let __t1427 = __v5 * __t1418;
            let __t1428 = __v4 * __t1374;
            let __t1430 = __t1427 + __t1428;
            let __t1431 = __v5 * __t1374;
            let __t1433 = __v4 * __t1421;
            let __t1435 = __t1431 + __t1433;
            let __t1437 = __v5 * __t1414;
            let __t1439 = __v3 * __t1349;
            let __t1441 = __t1437 + __t1439;
            let __t1443 = __v3 * __t1374;
            let __t1445 = __t1422 - __t1443;
            let __t1446 = __v5 * __t1349;
            let __t1448 = __v3 * __t1421;
            let __t1449 = __t1446 + __t1448;
            let __t1450 = __v4 * __t1414;
            let __t1451 = __v3 * __t1344;
            let __t1453 = __t1450 + __t1451;
            let __t1454 = __v4 * __t1344;
            let __t1456 = __v3 * __t1418;
            let __t1458 = __t1454 + __t1456;
            let __t1461 = __v5 * __t1430;
            let __t1462 = __v4 * __t1435;
            let __t1464 = __t1461 + __t1462;
            let __t1465 = __v5 * __t1426;
            let __t1467 = __v3 * __t1435;
            let __t1469 = __t1465 + __t1467;
            let __t1470 = -__t1469;
            let __t1471 = __v4 * __t1426;
            let __t1472 = __v3 * __t1430;
            let __t1474 = __t1471 - __t1472;
            let __t1475 = __v5 * __t1441;
            let __t1477 = __v3 * __t1449;
            let __t1478 = __t1475 + __t1477;
            let __t1479 = __v4 * __t1441;
            let __t1481 = __v3 * __t1445;
            let __t1483 = __t1479 + __t1481;
            let __t1484 = -__t1483;
            let __t1485 = __v4 * __t1453;
            let __t1486 = __v3 * __t1458;
            let __t1488 = __t1485 + __t1486;
            let __t1712 = __t336 * __t353;
            let __t1713 = __t337 * __t353;
            let __t1714 = __t338 * __t353;
            let __t1718 = __t336 * __t1712;
            let __t1720 = __t224 - __t1718;
            let __t1721 = __t337 * __t1712;
            let __t1723 = __t226 - __t1721;
            let __t1724 = __t338 * __t1712;
            let __t1726 = __t228 - __t1724;
            let __t1738 = __t337 * __t1713;
            let __t1740 = __t231 - __t1738;
            let __t1741 = __t338 * __t1713;
            let __t1743 = __t233 - __t1741;
            let __t1755 = __t338 * __t1714;
            let __t1757 = __t236 - __t1755;
            let __t1837 = __t1252 * __t1712;
            let __t1839 = (-2f64) * __t1837;
            let __t1840 = __t1330 + __t1839;
            let __t1850 = __t1253 * __t1713;
            let __t1852 = (-2f64) * __t1850;
            let __t1853 = __t1362 + __t1852;
            let __t1863 = __t1254 * __t1714;
            let __t1865 = (-2f64) * __t1863;
            let __t1866 = __t1387 + __t1865;
            let __t1867 = __t1840 + __t1853;
            let __t1868 = __t1866 + __t1867;
            let __t1870 = __v5 * __t1868;
            let __t1871 = 0.5f64 * __t1870;
            let __t1872 = (-0.5f64) * __t1870;
            let __t1873 = __v4 * __t1868;
            let __t1874 = 0.5f64 * __t1873;
            let __t1875 = __v3 * __t1868;
            let __t1876 = 0.5f64 * __t1875;
            let __t1877 = (-0.5f64) * __t1875;
            let __t1878 = (-0.5f64) * __t1873;
            __GyroscopicSystem {
                a: __Matrix3::new(
                    __t1720,
                    __t1723,
                    __t1726,
                    __t1723,
                    __t1740,
                    __t1743,
                    __t1726,
                    __t1743,
                    __t1757,
                ),
                g: __Matrix3::new(
                    0f64,
                    __t1872,
                    __t1874,
                    __t1871,
                    0f64,
                    __t1877,
                    __t1878,
                    __t1876,
                    0f64,
                ),
                c: __Matrix3::new(
                    __t1464,
                    __t1470,
                    __t1474,
                    __t1470,
                    __t1478,
                    __t1484,
                    __t1474,
                    __t1484,
                    __t1488,
                ),
            }
        }
        #[inline]
        fn reduced_equations(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __ReducedEquations {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.inertia[0usize];
            let __v8: __F64 = self.inertia[1usize];
            let __v9: __F64 = self.inertia[2usize];
            let __v10: __F64 = self.semi_axes[0usize];
            let __v11: __F64 = self.semi_axes[1usize];
            let __v12: __F64 = self.semi_axes[2usize];
            let __v13: __F64 = self.offset[0usize];
            let __v14: __F64 = self.offset[1usize];
            let __v15: __F64 = self.offset[2usize];
            let __v16: __F64 = self.mass;
            let __v17: __F64 = self.g;
            let __t18 = __v10 * __v10;
            let __t19 = __v11 * __v11;
            let __t20 = __v12 * __v12;
            let __t22 = __v3 * __t18;
            let __t23 = __v4 * __t19;
            let __t24 = __v5 * __t20;
            let __t25 = __v3 * __t22;
            let __t26 = __v4 * __t23;
            let __t27 = __v5 * __t24;
            let __t28 = __t25 + __t26;
            let __t29 = __t27 + __t28;
            let __t30 = __t29.sqrt();
            let __t43 = 1.0f64 / __t30;
            let __t45 = __t22 * __t43;
            let __t47 = __t45 - __v13;
            let __t50 = __t23 * __t43;
            let __t52 = __t50 - __v14;
            let __t55 = __t24 * __t43;
            let __t57 = __t55 - __v15;
            let __t58 = __v0 * __v7;
            let __t59 = __v1 * __v8;
            let __t60 = __v2 * __v9;
            let __t66 = __v2 * __v4;
            let __t67 = __v1 * __v5;
            let __t69 = __t66 - __t67;
            let __t70 = __v0 * __v5;
            let __t71 = __v2 * __v3;
            let __t73 = __t70 - __t71;
            let __t74 = __v1 * __v3;
            let __t75 = __v0 * __v4;
            let __t77 = __t74 - __t75;
            let __t78 = __t47 * __t69;
            let __t79 = __t52 * __t73;
            let __t80 = __t57 * __t77;
            let __t81 = __t78 + __t79;
            let __t82 = __t80 + __t81;
            let __t87 = __v16 * __v17;
            let __t91 = __v5 * __t52;
            let __t93 = __v4 * __t57;
            let __t95 = __t91 - __t93;
            let __t97 = __t82 * __t95;
            let __t99 = __v16 * __t97;
            let __t105 = __v5 * __t47;
            let __t107 = __v3 * __t57;
            let __t108 = __t107 - __t105;
            let __t109 = __t82 * __t108;
            let __t111 = __v16 * __t109;
            let __t117 = __v3 * __t52;
            let __t119 = __v4 * __t47;
            let __t120 = __t119 - __t117;
            let __t121 = __t82 * __t120;
            let __t123 = __v16 * __t121;
            let __t128 = __t47 * __t87;
            let __t131 = __t43 * __t43;
            let __t132 = __t45 * __t131;
            let __t134 = __t23 * __t132;
            let __t136 = __t73 * __t134;
            let __t138 = __v2 * __t52;
            let __t140 = __t136 + __t138;
            let __t142 = __t18 * __t43;
            let __t143 = __t22 * __t132;
            let __t145 = __t142 - __t143;
            let __t146 = __t69 * __t145;
            let __t147 = __t146 - __t140;
            let __t148 = __t24 * __t132;
            let __t150 = __t77 * __t148;
            let __t152 = __v1 * __t57;
            let __t153 = __t152 - __t150;
            let __t154 = __t147 + __t153;
            let __t155 = __t82 * __t154;
            let __t157 = __v16 * __t155;
            let __t159 = __t157 - __t128;
            let __t160 = __t52 * __t87;
            let __t162 = __t50 * __t131;
            let __t164 = __t19 * __t43;
            let __t165 = __t23 * __t162;
            let __t167 = __t164 - __t165;
            let __t168 = __t73 * __t167;
            let __t169 = __t22 * __t162;
            let __t171 = __t69 * __t169;
            let __t173 = __v2 * __t47;
            let __t174 = __t173 - __t171;
            let __t175 = __t168 + __t174;
            let __t177 = __t24 * __t162;
            let __t179 = __t77 * __t177;
            let __t181 = __v0 * __t57;
            let __t183 = __t179 + __t181;
            let __t185 = __t175 - __t183;
            let __t186 = __t82 * __t185;
            let __t188 = __v16 * __t186;
            let __t190 = __t188 - __t160;
            let __t191 = __t57 * __t87;
            let __t193 = __t55 * __t131;
            let __t195 = __t23 * __t193;
            let __t197 = __t73 * __t195;
            let __t199 = __v0 * __t52;
            let __t200 = __t199 - __t197;
            let __t202 = __t22 * __t193;
            let __t204 = __t69 * __t202;
            let __t206 = __v1 * __t47;
            let __t208 = __t204 + __t206;
            let __t210 = __t200 - __t208;
            let __t211 = __t20 * __t43;
            let __t212 = __t24 * __t193;
            let __t214 = __t211 - __t212;
            let __t215 = __t77 * __t214;
            let __t216 = __t210 + __t215;
            let __t217 = __t82 * __t216;
            let __t219 = __v16 * __t217;
            let __t221 = __t219 - __t191;
            let __t222 = __t95 * __t95;
            let __t223 = __v16 * __t222;
            let __t224 = __v7 + __t223;
            let __t225 = __t95 * __t108;
            let __t226 = __v16 * __t225;
            let __t227 = __t95 * __t120;
            let __t228 = __v16 * __t227;
            let __t229 = __t108 * __t108;
            let __t230 = __v16 * __t229;
            let __t231 = __v8 + __t230;
            let __t232 = __t108 * __t120;
            let __t233 = __v16 * __t232;
            let __t234 = __t120 * __t120;
            let __t235 = __v16 * __t234;
            let __t236 = __v9 + __t235;
            let __t237 = __v4 * __t148;
            let __t239 = __v5 * __t134;
            let __t241 = __t237 - __t239;
            let __t242 = __t95 * __t154;
            let __t243 = __t82 * __t241;
            let __t244 = __t242 + __t243;
            let __t245 = __v16 * __t244;
            let __t246 = __v4 * __t177;
            let __t248 = __t57 - __t246;
            let __t250 = __v5 * __t167;
            let __t251 = __t250 - __t248;
            let __t252 = __t95 * __t185;
            let __t253 = __t82 * __t251;
            let __t254 = __t252 + __t253;
            let __t255 = __v16 * __t254;
            let __t256 = __v4 * __t214;
            let __t258 = __v5 * __t195;
            let __t260 = __t52 - __t258;
            let __t261 = __t260 - __t256;
            let __t262 = __t95 * __t216;
            let __t263 = __t82 * __t261;
            let __t264 = __t262 + __t263;
            let __t265 = __v16 * __t264;
            let __t266 = __v3 * __t148;
            let __t268 = __t57 - __t266;
            let __t269 = __v5 * __t145;
            let __t271 = __t268 - __t269;
            let __t272 = __t108 * __t154;
            let __t273 = __t82 * __t271;
            let __t274 = __t272 + __t273;
            let __t275 = __v16 * __t274;
            let __t276 = __v3 * __t177;
            let __t278 = __v5 * __t169;
            let __t280 = __t278 - __t276;
            let __t281 = __t108 * __t185;
            let __t282 = __t82 * __t280;
            let __t283 = __t281 + __t282;
            let __t284 = __v16 * __t283;
            let __t285 = __v3 * __t214;
            let __t286 = __v5 * __t202;
            let __t288 = __t47 - __t286;
            let __t290 = __t285 - __t288;
            let __t291 = __t108 * __t216;
            let __t292 = __t82 * __t290;
            let __t293 = __t291 + __t292;
            let __t294 = __v16 * __t293;
            let __t295 = __v4 * __t145;
            let __t296 = __v3 * __t134;
            let __t298 = __t52 - __t296;
            let __t300 = __t295 - __t298;
            let __t301 = __t120 * __t154;
            let __t302 = __t82 * __t300;
            let __t303 = __t301 + __t302;
            let __t304 = __v16 * __t303;
            let __t305 = __v4 * __t169;
            let __t307 = __t47 - __t305;
            let __t308 = __v3 * __t167;
            let __t310 = __t307 - __t308;
            let __t311 = __t120 * __t185;
            let __t312 = __t82 * __t310;
            let __t313 = __t311 + __t312;
            let __t314 = __v16 * __t313;
            let __t315 = __v4 * __t202;
            let __t317 = __v3 * __t195;
            let __t319 = __t317 - __t315;
            let __t320 = __t120 * __t216;
            let __t321 = __t82 * __t319;
            let __t322 = __t320 + __t321;
            let __t323 = __v16 * __t322;
            let __t336 = __v3 * __v7;
            let __t337 = __v4 * __v8;
            let __t338 = __v5 * __v9;
            let __t339 = __v3 * __t336;
            let __t340 = __v4 * __t337;
            let __t341 = __v5 * __t338;
            let __t342 = __t339 + __t340;
            let __t343 = __t341 + __t342;
            let __t353 = 1.0f64 / __t343;
            let __t398 = 2f64 * __t336;
            let __t399 = 2f64 * __t337;
            let __t400 = 2f64 * __t338;
            let __t1667 = __v4 * __t59;
            let __t1668 = __v1 * __t337;
            let __t1669 = __t1667 + __t1668;
            let __t1670 = __v3 * __t58;
            let __t1671 = __v0 * __t336;
            let __t1672 = __t1670 + __t1671;
            let __t1673 = __t1669 + __t1672;
            let __t1674 = __v5 * __t60;
            let __t1675 = __v2 * __t338;
            let __t1676 = __t1674 + __t1675;
            let __t1677 = __t1673 + __t1676;
            let __t1679 = (-0.5f64) * __t1677;
            let __t1680 = __v6 + __t1679;
            let __t1681 = __t353 * __t1680;
            let __t1691 = __t336 * __t1681;
            let __t1692 = __t337 * __t1681;
            let __t1693 = __t338 * __t1681;
            let __t1694 = __t58 + __t1691;
            let __t1695 = __t59 + __t1692;
            let __t1696 = __t60 + __t1693;
            let __t1697 = __t99 + __t1694;
            let __t1698 = __t111 + __t1695;
            let __t1699 = __t123 + __t1696;
            let __t1700 = __t1681 * __t1694;
            let __t1701 = __t159 + __t1700;
            let __t1702 = __t1681 * __t1695;
            let __t1703 = __t190 + __t1702;
            let __t1704 = __t1681 * __t1696;
            let __t1705 = __t221 + __t1704;
            let __t1706 = __t398 * __t1681;
            let __t1707 = __t58 + __t1706;
            let __t1708 = __t399 * __t1681;
            let __t1709 = __t59 + __t1708;
            let __t1710 = __t400 * __t1681;
            let __t1711 = __t60 + __t1710;
            let __t1712 = __t336 * __t353;
            let __t1713 = __t337 * __t353;
            let __t1714 = __t338 * __t353;
            let __t1727 = __v7 * __t1681;
            let __t1728 = __t245 + __t1727;
            let __t1729 = __t1707 * __t1712;
            let __t1731 = __t1728 - __t1729;
            let __t1732 = __t1709 * __t1712;
            let __t1734 = __t255 - __t1732;
            let __t1735 = __t1711 * __t1712;
            let __t1737 = __t265 - __t1735;
            let __t1744 = __t1707 * __t1713;
            let __t1746 = __t275 - __t1744;
            let __t1747 = __v8 * __t1681;
            let __t1748 = __t284 + __t1747;
            let __t1749 = __t1709 * __t1713;
            let __t1751 = __t1748 - __t1749;
            let __t1752 = __t1711 * __t1713;
            let __t1754 = __t294 - __t1752;
            let __t1758 = __t1707 * __t1714;
            let __t1760 = __t304 - __t1758;
            let __t1761 = __t1709 * __t1714;
            let __t1763 = __t314 - __t1761;
            let __t1764 = __v9 * __t1681;
            let __t1765 = __t323 + __t1764;
            let __t1766 = __t1711 * __t1714;
            let __t1768 = __t1765 - __t1766;
            let __t1927 = __t69 * __t1731;
            let __t1928 = __t73 * __t1734;
            let __t1929 = __t77 * __t1737;
            let __t1930 = __t1927 + __t1928;
            let __t1931 = __t1929 + __t1930;
            let __t1932 = __t69 * __t1746;
            let __t1933 = __t73 * __t1751;
            let __t1934 = __t77 * __t1754;
            let __t1935 = __t1932 + __t1933;
            let __t1936 = __t1934 + __t1935;
            let __t1937 = __t69 * __t1760;
            let __t1938 = __t73 * __t1763;
            let __t1939 = __t77 * __t1768;
            let __t1940 = __t1937 + __t1938;
            let __t1941 = __t1939 + __t1940;
            let __t1942 = __v2 * __t1698;
            let __t1943 = __v1 * __t1699;
            let __t1945 = __t1942 - __t1943;
            let __t1946 = __v0 * __t1699;
            let __t1947 = __v2 * __t1697;
            let __t1949 = __t1946 - __t1947;
            let __t1950 = __v1 * __t1697;
            let __t1951 = __v0 * __t1698;
            let __t1953 = __t1950 - __t1951;
            let __t1954 = __v5 * __t1703;
            let __t1955 = __v4 * __t1705;
            let __t1957 = __t1954 - __t1955;
            let __t1958 = __v3 * __t1705;
            let __t1959 = __v5 * __t1701;
            let __t1961 = __t1958 - __t1959;
            let __t1962 = __v4 * __t1701;
            let __t1963 = __v3 * __t1703;
            let __t1965 = __t1962 - __t1963;
            let __t1966 = __t1945 + __t1957;
            let __t1968 = __t1966 - __t1931;
            let __t1969 = __t1949 + __t1961;
            let __t1971 = __t1969 - __t1936;
            let __t1972 = __t1953 + __t1965;
            let __t1974 = __t1972 - __t1941;
            __ReducedEquations {
                inertia: __Matrix3::new(
                    __t224,
                    __t226,
                    __t228,
                    __t226,
                    __t231,
                    __t233,
                    __t228,
                    __t233,
                    __t236,
                ),
                right_side: __Vector3::new(__t1968, __t1971, __t1974),
                psi_dot: __t1681,
                rank_one: __MaybeRankOne::Some(__RankOneInertia {
                    weight: __v16,
                    vector: __Vector3::new(__t95, __t108, __t120),
                }),
            }
        }
        #[inline]
        fn certification_tape(&self) -> __MaybeTape {
            __RouthTape::parse(
                "g 0;g 1;g 2;p;f 0;f 1;f 2;f 3;f 4;f 5;f 6;f 7;f 8;f 9;f 10;^ 7 2;^ 8 2;^ 9 2;* 0 15;* 1 16;* 2 17;* 0 18;* 1 19;* 2 20;+ 21 22;+ 23 24;F sqrt 25;- 10;/ 26;* 18 28;+ 27 29;- 11;* 19 28;+ 31 32;- 12;* 20 28;+ 34 35;* 13 14;* 30 37;- 38;^ 28 2;* 29 40;* 15 28;* 18 41;- 43;+ 42 44;* 33 37;- 46;* 32 40;* 16 28;* 19 48;- 50;+ 49 51;* 18 48;* 36 37;- 54;* 35 40;* 19 56;* 18 56;* 17 28;* 20 56;- 60;+ 59 61;* 0 4;* 1 5;* 2 6;* 0 63;* 1 64;* 2 65;+ 66 67;+ 68 69;/ 70;* 37 45;- 72;* 37 53;* 37 58;* 37 52;- 76;* 37 57;* 37 62;- 79;* 3 71;* 63 81;* 64 81;* 65 81;* 81 82;+ 39 85;* 81 83;+ 47 87;* 81 84;+ 55 89;* 71 82;* 71 83;* 71 84;* 4 81;* 81 94;+ 73 95;* 82 91;c c010000000000000;* 98 97;+ 96 99;* 83 91;* 98 101;+ 74 102;* 84 91;* 98 104;+ 75 105;* 5 81;* 81 107;+ 77 108;* 83 92;* 98 110;+ 109 111;* 84 92;* 98 113;+ 78 114;* 6 81;* 81 116;+ 80 117;* 84 93;* 98 119;+ 118 120;o 86 88 90 100 103 106 112 115 121",
                &[
                    self.inertia[0usize],
                    self.inertia[1usize],
                    self.inertia[2usize],
                    self.semi_axes[0usize],
                    self.semi_axes[1usize],
                    self.semi_axes[2usize],
                    self.offset[0usize],
                    self.offset[1usize],
                    self.offset[2usize],
                    self.mass,
                    self.g,
                ],
            )
        }
    }
    #[automatically_derived]
    impl ::routh::__private::DerivedFormulas for DiagonalEllipsoid {
        const LAGRANGIAN: &'static str = "0.5·(ω₃^2·inertia[2] + ω₁^2·inertia[0] + ω₂^2·inertia[1] + mass·((-offset[2] + γ₃·semi_axes[2]^2 / sqrt(γ₃^2·semi_axes[2]^2 + γ₁^2·semi_axes[0]^2 + γ₂^2·semi_axes[1]^2))·(ω₂·γ₁ - ω₁·γ₂) + (-offset[0] + γ₁·semi_axes[0]^2 / sqrt(γ₃^2·semi_axes[2]^2 + γ₁^2·semi_axes[0]^2 + γ₂^2·semi_axes[1]^2))·(ω₃·γ₂ - ω₂·γ₃) + (-offset[1] + γ₂·semi_axes[1]^2 / sqrt(γ₃^2·semi_axes[2]^2 + γ₁^2·semi_axes[0]^2 + γ₂^2·semi_axes[1]^2))·(ω₁·γ₃ - ω₃·γ₁))^2) - (sqrt(γ₃^2·semi_axes[2]^2 + γ₁^2·semi_axes[0]^2 + γ₂^2·semi_axes[1]^2) - (γ₃·offset[2] + γ₁·offset[0] + γ₂·offset[1]))·mass·g";
        const AMENDED_POTENTIAL: &'static str = "(sqrt(γ₃^2·semi_axes[2]^2 + γ₁^2·semi_axes[0]^2 + γ₂^2·semi_axes[1]^2) - (γ₃·offset[2] + γ₁·offset[0] + γ₂·offset[1]))·mass·g + 0.5·p_ψ^2 / (γ₃^2·inertia[2] + γ₁^2·inertia[0] + γ₂^2·inertia[1])";
        const PSI_DOT_AT_REST: &'static str = "p_ψ / (γ₃^2·inertia[2] + γ₁^2·inertia[0] + γ₂^2·inertia[1])";
    }
};
