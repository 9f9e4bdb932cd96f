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
    type __FullJacobian = ::routh::__private::FullJacobian;
    type __ReducedEquations = ::routh::__private::ReducedEquations;
    type __Op = ::routh::__private::Op;
    type __Output = ::routh::__private::Output;
    type __Tape = ::routh::__private::Tape;
    type __Func = ::routh::__private::Func;
    type __CertificationTape = ::routh::__private::CertificationTape;
    type __RouthianTape = ::routh::__private::RouthianTape;
    type __MaybeTape = ::routh::__private::MaybeTape;
    type __MaybeRouthianTape = ::routh::__private::MaybeRouthianTape;
    type __FlowTape = ::routh::__private::FlowTape;
    type __MaybeFlowTape = ::routh::__private::MaybeFlowTape;
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
            let __t66 = __v4 * __v2;
            let __t67 = __v5 * __v1;
            let __t70 = __v5 * __v0;
            let __t71 = __v3 * __v2;
            let __t74 = __v3 * __v1;
            let __t22 = __t18 * __v3;
            let __t23 = __t19 * __v4;
            let __t24 = __t20 * __v5;
            let __t75 = __v4 * __v0;
            let __t69 = __t66 - __t67;
            let __t58 = __v7 * __v0;
            let __t73 = __t70 - __t71;
            let __t59 = __v8 * __v1;
            let __t25 = __t22 * __v3;
            let __t26 = __t23 * __v4;
            let __t27 = __t24 * __v5;
            let __t77 = __t74 - __t75;
            let __t31 = __v13 * __v3;
            let __t32 = __v14 * __v4;
            let __t60 = __v9 * __v2;
            let __t61 = __t58 * __v0;
            let __t62 = __t59 * __v1;
            let __t28 = __t26 + __t25;
            let __t33 = __v15 * __v5;
            let __t87 = __v17 * __v16;
            let __t34 = __t32 + __t31;
            let __t63 = __t60 * __v2;
            let __t64 = __t62 + __t61;
            let __t29 = __t28 + __t27;
            let __t35 = __t34 + __t33;
            let __t65 = __t64 + __t63;
            let __t30 = __t29.sqrt();
            let __t43 = 1.0f64 / __t30;
            let __t37 = __t30 - __t35;
            let __t88 = __t37 * __t87;
            let __t45 = __t43 * __t22;
            let __t50 = __t43 * __t23;
            let __t55 = __t43 * __t24;
            let __t47 = __t45 - __v13;
            let __t52 = __t50 - __v14;
            let __t57 = __t55 - __v15;
            let __t78 = __t47 * __t69;
            let __t79 = __t52 * __t73;
            let __t80 = __t57 * __t77;
            let __t81 = __t79 + __t78;
            let __t82 = __t81 + __t80;
            let __t83 = __t82 * __t82;
            let __t84 = __t83 * __v16;
            let __t85 = __t84 + __t65;
            let __t86 = __t85 * 0.5f64;
            let __t114 = __t86 - __t88;
            __t114
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
            let __t66 = __v4 * __v2;
            let __t67 = __v5 * __v1;
            let __t70 = __v5 * __v0;
            let __t71 = __v3 * __v2;
            let __t74 = __v3 * __v1;
            let __t22 = __t18 * __v3;
            let __t23 = __t19 * __v4;
            let __t24 = __t20 * __v5;
            let __t75 = __v4 * __v0;
            let __t69 = __t66 - __t67;
            let __t58 = __v7 * __v0;
            let __t73 = __t70 - __t71;
            let __t59 = __v8 * __v1;
            let __t25 = __t22 * __v3;
            let __t26 = __t23 * __v4;
            let __t27 = __t24 * __v5;
            let __t77 = __t74 - __t75;
            let __t60 = __v9 * __v2;
            let __t28 = __t26 + __t25;
            let __t29 = __t28 + __t27;
            let __t30 = __t29.sqrt();
            let __t43 = 1.0f64 / __t30;
            let __t45 = __t43 * __t22;
            let __t50 = __t43 * __t23;
            let __t55 = __t43 * __t24;
            let __t47 = __t45 - __v13;
            let __t52 = __t50 - __v14;
            let __t57 = __t55 - __v15;
            let __t78 = __t47 * __t69;
            let __t79 = __t52 * __t73;
            let __t80 = __t57 * __t77;
            let __t98 = __t52 * __v5;
            let __t100 = __t57 * __v4;
            let __t104 = __t47 * __v5;
            let __t106 = __t57 * __v3;
            let __t109 = __t52 * __v3;
            let __t111 = __t47 * __v4;
            let __t81 = __t79 + __t78;
            let __t102 = __t98 - __t100;
            let __t107 = __t106 - __t104;
            let __t112 = __t111 - __t109;
            let __t82 = __t81 + __t80;
            let __t116 = __t82 * __t102;
            let __t122 = __t82 * __t107;
            let __t128 = __t82 * __t112;
            let __t118 = __t116 * __v16;
            let __t124 = __t122 * __v16;
            let __t130 = __t128 * __v16;
            let __t121 = __t118 + __t58;
            let __t127 = __t124 + __t59;
            let __t133 = __t130 + __t60;
            __Vector3::new(__t121, __t127, __t133)
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
            let __t66 = __v4 * __v2;
            let __t67 = __v5 * __v1;
            let __t70 = __v5 * __v0;
            let __t71 = __v3 * __v2;
            let __t74 = __v3 * __v1;
            let __t22 = __t18 * __v3;
            let __t23 = __t19 * __v4;
            let __t24 = __t20 * __v5;
            let __t75 = __v4 * __v0;
            let __t69 = __t66 - __t67;
            let __t87 = __v17 * __v16;
            let __t73 = __t70 - __t71;
            let __t25 = __t22 * __v3;
            let __t26 = __t23 * __v4;
            let __t27 = __t24 * __v5;
            let __t77 = __t74 - __t75;
            let __t28 = __t26 + __t25;
            let __t29 = __t28 + __t27;
            let __t30 = __t29.sqrt();
            let __t43 = 1.0f64 / __t30;
            let __t45 = __t43 * __t22;
            let __t50 = __t43 * __t23;
            let __t55 = __t43 * __t24;
            let __t137 = __t43 * __t43;
            let __t148 = __t43 * __t18;
            let __t170 = __t43 * __t19;
            let __t217 = __t43 * __t20;
            let __t47 = __t45 - __v13;
            let __t52 = __t50 - __v14;
            let __t57 = __t55 - __v15;
            let __t138 = __t137 * __t45;
            let __t168 = __t137 * __t50;
            let __t199 = __t137 * __t55;
            let __t179 = __t47 * __v2;
            let __t144 = __t52 * __v2;
            let __t205 = __t52 * __v0;
            let __t140 = __t138 * __t23;
            let __t149 = __t138 * __t22;
            let __t171 = __t168 * __t23;
            let __t175 = __t168 * __t22;
            let __t201 = __t199 * __t23;
            let __t208 = __t199 * __t22;
            let __t154 = __t138 * __t24;
            let __t183 = __t168 * __t24;
            let __t142 = __t140 * __t73;
            let __t151 = __t148 - __t149;
            let __t173 = __t170 - __t171;
            let __t177 = __t175 * __t69;
            let __t203 = __t201 * __t73;
            let __t210 = __t208 * __t69;
            let __t212 = __t47 * __v1;
            let __t218 = __t199 * __t24;
            let __t78 = __t47 * __t69;
            let __t79 = __t52 * __t73;
            let __t146 = __t142 + __t144;
            let __t152 = __t151 * __t69;
            let __t156 = __t154 * __t77;
            let __t158 = __t57 * __v1;
            let __t174 = __t173 * __t73;
            let __t180 = __t179 - __t177;
            let __t185 = __t183 * __t77;
            let __t187 = __t57 * __v0;
            let __t206 = __t205 - __t203;
            let __t214 = __t212 + __t210;
            let __t220 = __t217 - __t218;
            let __t80 = __t57 * __t77;
            let __t81 = __t79 + __t78;
            let __t153 = __t152 - __t146;
            let __t159 = __t158 - __t156;
            let __t181 = __t180 + __t174;
            let __t189 = __t187 + __t185;
            let __t216 = __t206 - __t214;
            let __t221 = __t220 * __t77;
            let __t134 = __t47 * __t87;
            let __t82 = __t81 + __t80;
            let __t166 = __t52 * __t87;
            let __t160 = __t159 + __t153;
            let __t197 = __t57 * __t87;
            let __t191 = __t181 - __t189;
            let __t222 = __t221 + __t216;
            let __t161 = __t160 * __t82;
            let __t192 = __t191 * __t82;
            let __t223 = __t222 * __t82;
            let __t163 = __t161 * __v16;
            let __t194 = __t192 * __v16;
            let __t225 = __t223 * __v16;
            let __t165 = __t163 - __t134;
            let __t196 = __t194 - __t166;
            let __t227 = __t225 - __t197;
            __Vector3::new(__t165, __t196, __t227)
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
            let __t22 = __t18 * __v3;
            let __t23 = __t19 * __v4;
            let __t24 = __t20 * __v5;
            let __t25 = __t22 * __v3;
            let __t26 = __t23 * __v4;
            let __t27 = __t24 * __v5;
            let __t28 = __t26 + __t25;
            let __t29 = __t28 + __t27;
            let __t30 = __t29.sqrt();
            let __t43 = 1.0f64 / __t30;
            let __t45 = __t43 * __t22;
            let __t50 = __t43 * __t23;
            let __t55 = __t43 * __t24;
            let __t47 = __t45 - __v13;
            let __t52 = __t50 - __v14;
            let __t57 = __t55 - __v15;
            let __t104 = __t47 * __v5;
            let __t98 = __t52 * __v5;
            let __t100 = __t57 * __v4;
            let __t106 = __t57 * __v3;
            let __t109 = __t52 * __v3;
            let __t111 = __t47 * __v4;
            let __t102 = __t98 - __t100;
            let __t107 = __t106 - __t104;
            let __t112 = __t111 - __t109;
            let __t228 = __t102 * __t102;
            let __t235 = __t107 * __t107;
            let __t231 = __t107 * __t102;
            let __t240 = __t112 * __t112;
            let __t233 = __t112 * __t102;
            let __t238 = __t112 * __t107;
            let __t229 = __t228 * __v16;
            let __t236 = __t235 * __v16;
            let __t232 = __t231 * __v16;
            let __t241 = __t240 * __v16;
            let __t234 = __t233 * __v16;
            let __t239 = __t238 * __v16;
            let __t230 = __t229 + __v7;
            let __t237 = __t236 + __v8;
            let __t242 = __t241 + __v9;
            __Matrix3::new(
                __t230,
                __t232,
                __t234,
                __t232,
                __t237,
                __t239,
                __t234,
                __t239,
                __t242,
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
            let __t66 = __v4 * __v2;
            let __t67 = __v5 * __v1;
            let __t70 = __v5 * __v0;
            let __t71 = __v3 * __v2;
            let __t74 = __v3 * __v1;
            let __t22 = __t18 * __v3;
            let __t23 = __t19 * __v4;
            let __t24 = __t20 * __v5;
            let __t75 = __v4 * __v0;
            let __t69 = __t66 - __t67;
            let __t73 = __t70 - __t71;
            let __t25 = __t22 * __v3;
            let __t26 = __t23 * __v4;
            let __t27 = __t24 * __v5;
            let __t77 = __t74 - __t75;
            let __t28 = __t26 + __t25;
            let __t29 = __t28 + __t27;
            let __t30 = __t29.sqrt();
            let __t43 = 1.0f64 / __t30;
            let __t45 = __t43 * __t22;
            let __t50 = __t43 * __t23;
            let __t55 = __t43 * __t24;
            let __t137 = __t43 * __t43;
            let __t148 = __t43 * __t18;
            let __t170 = __t43 * __t19;
            let __t217 = __t43 * __t20;
            let __t47 = __t45 - __v13;
            let __t52 = __t50 - __v14;
            let __t57 = __t55 - __v15;
            let __t138 = __t137 * __t45;
            let __t168 = __t137 * __t50;
            let __t199 = __t137 * __t55;
            let __t179 = __t47 * __v2;
            let __t144 = __t52 * __v2;
            let __t205 = __t52 * __v0;
            let __t140 = __t138 * __t23;
            let __t149 = __t138 * __t22;
            let __t171 = __t168 * __t23;
            let __t175 = __t168 * __t22;
            let __t201 = __t199 * __t23;
            let __t208 = __t199 * __t22;
            let __t154 = __t138 * __t24;
            let __t183 = __t168 * __t24;
            let __t142 = __t140 * __t73;
            let __t151 = __t148 - __t149;
            let __t173 = __t170 - __t171;
            let __t177 = __t175 * __t69;
            let __t203 = __t201 * __t73;
            let __t210 = __t208 * __t69;
            let __t212 = __t47 * __v1;
            let __t218 = __t199 * __t24;
            let __t78 = __t47 * __t69;
            let __t79 = __t52 * __t73;
            let __t146 = __t142 + __t144;
            let __t152 = __t151 * __t69;
            let __t156 = __t154 * __t77;
            let __t158 = __t57 * __v1;
            let __t174 = __t173 * __t73;
            let __t180 = __t179 - __t177;
            let __t185 = __t183 * __t77;
            let __t187 = __t57 * __v0;
            let __t206 = __t205 - __t203;
            let __t214 = __t212 + __t210;
            let __t220 = __t217 - __t218;
            let __t252 = __t183 * __v4;
            let __t264 = __t201 * __v5;
            let __t272 = __t154 * __v3;
            let __t292 = __t208 * __v5;
            let __t302 = __t140 * __v3;
            let __t311 = __t175 * __v4;
            let __t80 = __t57 * __t77;
            let __t81 = __t79 + __t78;
            let __t98 = __t52 * __v5;
            let __t100 = __t57 * __v4;
            let __t104 = __t47 * __v5;
            let __t106 = __t57 * __v3;
            let __t109 = __t52 * __v3;
            let __t111 = __t47 * __v4;
            let __t153 = __t152 - __t146;
            let __t159 = __t158 - __t156;
            let __t181 = __t180 + __t174;
            let __t189 = __t187 + __t185;
            let __t216 = __t206 - __t214;
            let __t221 = __t220 * __t77;
            let __t243 = __t154 * __v4;
            let __t245 = __t140 * __v5;
            let __t254 = __t57 - __t252;
            let __t256 = __t173 * __v5;
            let __t262 = __t220 * __v4;
            let __t266 = __t52 - __t264;
            let __t274 = __t57 - __t272;
            let __t275 = __t151 * __v5;
            let __t282 = __t183 * __v3;
            let __t284 = __t175 * __v5;
            let __t291 = __t220 * __v3;
            let __t294 = __t47 - __t292;
            let __t301 = __t151 * __v4;
            let __t304 = __t52 - __t302;
            let __t313 = __t47 - __t311;
            let __t314 = __t173 * __v3;
            let __t321 = __t208 * __v4;
            let __t323 = __t201 * __v3;
            let __t82 = __t81 + __t80;
            let __t102 = __t98 - __t100;
            let __t107 = __t106 - __t104;
            let __t112 = __t111 - __t109;
            let __t160 = __t159 + __t153;
            let __t191 = __t181 - __t189;
            let __t222 = __t221 + __t216;
            let __t247 = __t243 - __t245;
            let __t257 = __t256 - __t254;
            let __t267 = __t266 - __t262;
            let __t277 = __t274 - __t275;
            let __t286 = __t284 - __t282;
            let __t296 = __t291 - __t294;
            let __t306 = __t301 - __t304;
            let __t316 = __t313 - __t314;
            let __t325 = __t323 - __t321;
            let __t248 = __t160 * __t102;
            let __t249 = __t247 * __t82;
            let __t258 = __t191 * __t102;
            let __t259 = __t257 * __t82;
            let __t268 = __t222 * __t102;
            let __t269 = __t267 * __t82;
            let __t278 = __t160 * __t107;
            let __t279 = __t277 * __t82;
            let __t287 = __t191 * __t107;
            let __t288 = __t286 * __t82;
            let __t297 = __t222 * __t107;
            let __t298 = __t296 * __t82;
            let __t307 = __t160 * __t112;
            let __t308 = __t306 * __t82;
            let __t317 = __t191 * __t112;
            let __t318 = __t316 * __t82;
            let __t326 = __t222 * __t112;
            let __t327 = __t325 * __t82;
            let __t250 = __t249 + __t248;
            let __t260 = __t259 + __t258;
            let __t270 = __t269 + __t268;
            let __t280 = __t279 + __t278;
            let __t289 = __t288 + __t287;
            let __t299 = __t298 + __t297;
            let __t309 = __t308 + __t307;
            let __t319 = __t318 + __t317;
            let __t328 = __t327 + __t326;
            let __t251 = __t250 * __v16;
            let __t261 = __t260 * __v16;
            let __t271 = __t270 * __v16;
            let __t281 = __t280 * __v16;
            let __t290 = __t289 * __v16;
            let __t300 = __t299 * __v16;
            let __t310 = __t309 * __v16;
            let __t320 = __t319 * __v16;
            let __t329 = __t328 * __v16;
            __Matrix3::new(
                __t251,
                __t261,
                __t271,
                __t281,
                __t290,
                __t300,
                __t310,
                __t320,
                __t329,
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
            let __t66 = __v4 * __v2;
            let __t67 = __v5 * __v1;
            let __t70 = __v5 * __v0;
            let __t71 = __v3 * __v2;
            let __t74 = __v3 * __v1;
            let __t22 = __t18 * __v3;
            let __t23 = __t19 * __v4;
            let __t24 = __t20 * __v5;
            let __t75 = __v4 * __v0;
            let __t69 = __t66 - __t67;
            let __t58 = __v7 * __v0;
            let __t73 = __t70 - __t71;
            let __t59 = __v8 * __v1;
            let __t25 = __t22 * __v3;
            let __t26 = __t23 * __v4;
            let __t27 = __t24 * __v5;
            let __t77 = __t74 - __t75;
            let __t31 = __v13 * __v3;
            let __t32 = __v14 * __v4;
            let __t60 = __v9 * __v2;
            let __t61 = __t58 * __v0;
            let __t62 = __t59 * __v1;
            let __t28 = __t26 + __t25;
            let __t33 = __v15 * __v5;
            let __t87 = __v17 * __v16;
            let __t34 = __t32 + __t31;
            let __t63 = __t60 * __v2;
            let __t64 = __t62 + __t61;
            let __t29 = __t28 + __t27;
            let __t35 = __t34 + __t33;
            let __t65 = __t64 + __t63;
            let __t30 = __t29.sqrt();
            let __t43 = 1.0f64 / __t30;
            let __t37 = __t30 - __t35;
            let __t88 = __t37 * __t87;
            let __t45 = __t43 * __t22;
            let __t50 = __t43 * __t23;
            let __t55 = __t43 * __t24;
            let __t47 = __t45 - __v13;
            let __t52 = __t50 - __v14;
            let __t57 = __t55 - __v15;
            let __t78 = __t47 * __t69;
            let __t79 = __t52 * __t73;
            let __t80 = __t57 * __t77;
            let __t98 = __t52 * __v5;
            let __t100 = __t57 * __v4;
            let __t104 = __t47 * __v5;
            let __t106 = __t57 * __v3;
            let __t109 = __t52 * __v3;
            let __t111 = __t47 * __v4;
            let __t81 = __t79 + __t78;
            let __t102 = __t98 - __t100;
            let __t107 = __t106 - __t104;
            let __t112 = __t111 - __t109;
            let __t82 = __t81 + __t80;
            let __t116 = __t82 * __t102;
            let __t122 = __t82 * __t107;
            let __t83 = __t82 * __t82;
            let __t128 = __t82 * __t112;
            let __t118 = __t116 * __v16;
            let __t124 = __t122 * __v16;
            let __t84 = __t83 * __v16;
            let __t130 = __t128 * __v16;
            let __t121 = __t118 + __t58;
            let __t127 = __t124 + __t59;
            let __t85 = __t84 + __t65;
            let __t133 = __t130 + __t60;
            let __t330 = __t121 * __v0;
            let __t331 = __t127 * __v1;
            let __t86 = __t85 * 0.5f64;
            let __t332 = __t133 * __v2;
            let __t333 = __t331 + __t330;
            let __t114 = __t86 - __t88;
            let __t334 = __t333 + __t332;
            let __t336 = __t334 - __t114;
            __t336
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
            let __t58 = __v7 * __v0;
            let __t59 = __v8 * __v1;
            let __t342 = __v7 * __v3;
            let __t343 = __v8 * __v4;
            let __t60 = __v9 * __v2;
            let __t344 = __v9 * __v5;
            let __t1774 = __t58 * __v3;
            let __t1771 = __t59 * __v4;
            let __t1775 = __t342 * __v0;
            let __t1772 = __t343 * __v1;
            let __t1778 = __t60 * __v5;
            let __t1779 = __t344 * __v2;
            let __t1776 = __t1775 + __t1774;
            let __t1773 = __t1772 + __t1771;
            let __t1780 = __t1779 + __t1778;
            let __t1777 = __t1773 + __t1776;
            let __t1781 = __t1777 + __t1780;
            let __t1782 = __t1781 * 0.5f64;
            __t1782
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
            let __t66 = __v4 * __v2;
            let __t67 = __v5 * __v1;
            let __t70 = __v5 * __v0;
            let __t71 = __v3 * __v2;
            let __t74 = __v3 * __v1;
            let __t22 = __t18 * __v3;
            let __t23 = __t19 * __v4;
            let __t24 = __t20 * __v5;
            let __t75 = __v4 * __v0;
            let __t69 = __t66 - __t67;
            let __t87 = __v17 * __v16;
            let __t73 = __t70 - __t71;
            let __t58 = __v7 * __v0;
            let __t25 = __t22 * __v3;
            let __t26 = __t23 * __v4;
            let __t27 = __t24 * __v5;
            let __t77 = __t74 - __t75;
            let __t59 = __v8 * __v1;
            let __t60 = __v9 * __v2;
            let __t28 = __t26 + __t25;
            let __t29 = __t28 + __t27;
            let __t30 = __t29.sqrt();
            let __t43 = 1.0f64 / __t30;
            let __t45 = __t43 * __t22;
            let __t50 = __t43 * __t23;
            let __t55 = __t43 * __t24;
            let __t137 = __t43 * __t43;
            let __t148 = __t43 * __t18;
            let __t170 = __t43 * __t19;
            let __t217 = __t43 * __t20;
            let __t47 = __t45 - __v13;
            let __t52 = __t50 - __v14;
            let __t57 = __t55 - __v15;
            let __t138 = __t137 * __t45;
            let __t168 = __t137 * __t50;
            let __t199 = __t137 * __t55;
            let __t179 = __t47 * __v2;
            let __t144 = __t52 * __v2;
            let __t205 = __t52 * __v0;
            let __t140 = __t138 * __t23;
            let __t149 = __t138 * __t22;
            let __t171 = __t168 * __t23;
            let __t175 = __t168 * __t22;
            let __t201 = __t199 * __t23;
            let __t208 = __t199 * __t22;
            let __t154 = __t138 * __t24;
            let __t183 = __t168 * __t24;
            let __t142 = __t140 * __t73;
            let __t151 = __t148 - __t149;
            let __t173 = __t170 - __t171;
            let __t177 = __t175 * __t69;
            let __t203 = __t201 * __t73;
            let __t210 = __t208 * __t69;
            let __t212 = __t47 * __v1;
            let __t218 = __t199 * __t24;
            let __t78 = __t47 * __t69;
            let __t79 = __t52 * __t73;
            let __t146 = __t142 + __t144;
            let __t152 = __t151 * __t69;
            let __t156 = __t154 * __t77;
            let __t158 = __t57 * __v1;
            let __t174 = __t173 * __t73;
            let __t180 = __t179 - __t177;
            let __t185 = __t183 * __t77;
            let __t187 = __t57 * __v0;
            let __t206 = __t205 - __t203;
            let __t214 = __t212 + __t210;
            let __t220 = __t217 - __t218;
            let __t252 = __t183 * __v4;
            let __t272 = __t154 * __v3;
            let __t302 = __t140 * __v3;
            let __t311 = __t175 * __v4;
            let __t80 = __t57 * __t77;
            let __t81 = __t79 + __t78;
            let __t98 = __t52 * __v5;
            let __t100 = __t57 * __v4;
            let __t104 = __t47 * __v5;
            let __t106 = __t57 * __v3;
            let __t109 = __t52 * __v3;
            let __t111 = __t47 * __v4;
            let __t153 = __t152 - __t146;
            let __t159 = __t158 - __t156;
            let __t181 = __t180 + __t174;
            let __t189 = __t187 + __t185;
            let __t216 = __t206 - __t214;
            let __t221 = __t220 * __t77;
            let __t243 = __t154 * __v4;
            let __t245 = __t140 * __v5;
            let __t254 = __t57 - __t252;
            let __t256 = __t173 * __v5;
            let __t264 = __t201 * __v5;
            let __t274 = __t57 - __t272;
            let __t275 = __t151 * __v5;
            let __t282 = __t183 * __v3;
            let __t284 = __t175 * __v5;
            let __t292 = __t208 * __v5;
            let __t301 = __t151 * __v4;
            let __t304 = __t52 - __t302;
            let __t313 = __t47 - __t311;
            let __t314 = __t173 * __v3;
            let __t82 = __t81 + __t80;
            let __t102 = __t98 - __t100;
            let __t107 = __t106 - __t104;
            let __t112 = __t111 - __t109;
            let __t160 = __t159 + __t153;
            let __t191 = __t181 - __t189;
            let __t222 = __t221 + __t216;
            let __t247 = __t243 - __t245;
            let __t257 = __t256 - __t254;
            let __t262 = __t220 * __v4;
            let __t266 = __t52 - __t264;
            let __t277 = __t274 - __t275;
            let __t286 = __t284 - __t282;
            let __t291 = __t220 * __v3;
            let __t294 = __t47 - __t292;
            let __t306 = __t301 - __t304;
            let __t316 = __t313 - __t314;
            let __t321 = __t208 * __v4;
            let __t323 = __t201 * __v3;
            let __t116 = __t102 * __t82;
            let __t122 = __t107 * __t82;
            let __t128 = __t112 * __t82;
            let __t161 = __t160 * __t82;
            let __t192 = __t191 * __t82;
            let __t223 = __t222 * __t82;
            let __t248 = __t160 * __t102;
            let __t249 = __t247 * __t82;
            let __t258 = __t191 * __t102;
            let __t259 = __t257 * __t82;
            let __t267 = __t266 - __t262;
            let __t278 = __t160 * __t107;
            let __t279 = __t277 * __t82;
            let __t287 = __t191 * __t107;
            let __t288 = __t286 * __t82;
            let __t296 = __t291 - __t294;
            let __t307 = __t160 * __t112;
            let __t308 = __t306 * __t82;
            let __t317 = __t191 * __t112;
            let __t318 = __t316 * __t82;
            let __t325 = __t323 - __t321;
            let __t118 = __t116 * __v16;
            let __t124 = __t122 * __v16;
            let __t130 = __t128 * __v16;
            let __t134 = __t47 * __t87;
            let __t163 = __t161 * __v16;
            let __t166 = __t52 * __t87;
            let __t194 = __t192 * __v16;
            let __t197 = __t57 * __t87;
            let __t225 = __t223 * __v16;
            let __t250 = __t249 + __t248;
            let __t260 = __t259 + __t258;
            let __t268 = __t222 * __t102;
            let __t269 = __t267 * __t82;
            let __t280 = __t279 + __t278;
            let __t289 = __t288 + __t287;
            let __t297 = __t222 * __t107;
            let __t298 = __t296 * __t82;
            let __t309 = __t308 + __t307;
            let __t319 = __t318 + __t317;
            let __t326 = __t222 * __t112;
            let __t327 = __t325 * __t82;
            let __t121 = __t118 + __t58;
            let __t127 = __t124 + __t59;
            let __t133 = __t130 + __t60;
            let __t165 = __t163 - __t134;
            let __t196 = __t194 - __t166;
            let __t227 = __t225 - __t197;
            let __t251 = __t250 * __v16;
            let __t261 = __t260 * __v16;
            let __t270 = __t269 + __t268;
            let __t281 = __t280 * __v16;
            let __t290 = __t289 * __v16;
            let __t299 = __t298 + __t297;
            let __t310 = __t309 * __v16;
            let __t320 = __t319 * __v16;
            let __t328 = __t327 + __t326;
            let __t2070 = __t251 * __t69;
            let __t271 = __t270 * __v16;
            let __t2071 = __t261 * __t73;
            let __t2075 = __t281 * __t69;
            let __t300 = __t299 * __v16;
            let __t2076 = __t290 * __t73;
            let __t2080 = __t310 * __t69;
            let __t329 = __t328 * __v16;
            let __t2081 = __t320 * __t73;
            let __t2085 = __t127 * __v2;
            let __t2086 = __t133 * __v1;
            let __t2089 = __t133 * __v0;
            let __t2090 = __t121 * __v2;
            let __t2093 = __t121 * __v1;
            let __t2094 = __t127 * __v0;
            let __t2097 = __t196 * __v5;
            let __t2098 = __t227 * __v4;
            let __t2101 = __t227 * __v3;
            let __t2102 = __t165 * __v5;
            let __t2105 = __t165 * __v4;
            let __t2106 = __t196 * __v3;
            let __t228 = __t102 * __t102;
            let __t235 = __t107 * __t107;
            let __t240 = __t112 * __t112;
            let __t2072 = __t271 * __t77;
            let __t2073 = __t2071 + __t2070;
            let __t2077 = __t300 * __t77;
            let __t2078 = __t2076 + __t2075;
            let __t2082 = __t329 * __t77;
            let __t2083 = __t2081 + __t2080;
            let __t2088 = __t2085 - __t2086;
            let __t2092 = __t2089 - __t2090;
            let __t2096 = __t2093 - __t2094;
            let __t2100 = __t2097 - __t2098;
            let __t2104 = __t2101 - __t2102;
            let __t2108 = __t2105 - __t2106;
            let __t229 = __t228 * __v16;
            let __t231 = __t107 * __t102;
            let __t233 = __t112 * __t102;
            let __t236 = __t235 * __v16;
            let __t238 = __t112 * __t107;
            let __t241 = __t240 * __v16;
            let __t2074 = __t2073 + __t2072;
            let __t2079 = __t2078 + __t2077;
            let __t2084 = __t2083 + __t2082;
            let __t2109 = __t2100 + __t2088;
            let __t2112 = __t2104 + __t2092;
            let __t2115 = __t2108 + __t2096;
            let __t230 = __t229 + __v7;
            let __t232 = __t231 * __v16;
            let __t234 = __t233 * __v16;
            let __t237 = __t236 + __v8;
            let __t239 = __t238 * __v16;
            let __t242 = __t241 + __v9;
            let __t2111 = __t2109 - __t2074;
            let __t2114 = __t2112 - __t2079;
            let __t2117 = __t2115 - __t2084;
            __FullEquations {
                inertia: __Matrix3::new(
                    __t230,
                    __t232,
                    __t234,
                    __t232,
                    __t237,
                    __t239,
                    __t234,
                    __t239,
                    __t242,
                ),
                right_side: __Vector3::new(__t2111, __t2114, __t2117),
                rank_one: __MaybeRankOne::Some(__RankOneInertia {
                    weight: __v16,
                    vector: __Vector3::new(__t102, __t107, __t112),
                }),
            }
        }
        #[inline]
        fn full_jacobian(
            &self,
            __omega: &__Vector3,
            __gamma: &__Vector3,
        ) -> __FullJacobian {
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
            let __t66 = __v4 * __v2;
            let __t67 = __v5 * __v1;
            let __t70 = __v5 * __v0;
            let __t71 = __v3 * __v2;
            let __t74 = __v3 * __v1;
            let __t22 = __t18 * __v3;
            let __t23 = __t19 * __v4;
            let __t24 = __t20 * __v5;
            let __t75 = __v4 * __v0;
            let __t69 = __t66 - __t67;
            let __t87 = __v17 * __v16;
            let __t73 = __t70 - __t71;
            let __t58 = __v7 * __v0;
            let __t25 = __t22 * __v3;
            let __t26 = __t23 * __v4;
            let __t27 = __t24 * __v5;
            let __t77 = __t74 - __t75;
            let __t59 = __v8 * __v1;
            let __t60 = __v9 * __v2;
            let __t28 = __t26 + __t25;
            let __t29 = __t28 + __t27;
            let __t30 = __t29.sqrt();
            let __t43 = 1.0f64 / __t30;
            let __t45 = __t43 * __t22;
            let __t50 = __t43 * __t23;
            let __t55 = __t43 * __t24;
            let __t137 = __t43 * __t43;
            let __t148 = __t43 * __t18;
            let __t170 = __t43 * __t19;
            let __t217 = __t43 * __t20;
            let __t47 = __t45 - __v13;
            let __t52 = __t50 - __v14;
            let __t57 = __t55 - __v15;
            let __t138 = __t137 * __t45;
            let __t168 = __t137 * __t50;
            let __t199 = __t137 * __t55;
            let __t179 = __t47 * __v2;
            let __t144 = __t52 * __v2;
            let __t205 = __t52 * __v0;
            let __t641 = __t138 * __t43;
            let __t748 = __t168 * __t43;
            let __t847 = __t199 * __t43;
            let __t140 = __t138 * __t23;
            let __t154 = __t138 * __t24;
            let __t175 = __t168 * __t22;
            let __t183 = __t168 * __t24;
            let __t201 = __t199 * __t23;
            let __t208 = __t199 * __t22;
            let __t753 = __t748 * __t45;
            let __t852 = __t847 * __t45;
            let __t1053 = __t847 * __t50;
            let __t2345 = __t641 * __t50;
            let __t2391 = __t641 * __t55;
            let __t2464 = __t748 * __t55;
            let __t149 = __t138 * __t22;
            let __t171 = __t168 * __t23;
            let __t218 = __t199 * __t24;
            let __t751 = __t175 * __t137;
            let __t754 = __t753 * (-2f64);
            let __t850 = __t208 * __t137;
            let __t853 = __t852 * (-2f64);
            let __t1051 = __t201 * __t137;
            let __t1054 = __t1053 * (-2f64);
            let __t2343 = __t140 * __t137;
            let __t2346 = __t2345 * (-2f64);
            let __t2389 = __t154 * __t137;
            let __t2392 = __t2391 * (-2f64);
            let __t2462 = __t183 * __t137;
            let __t2465 = __t2464 * (-2f64);
            let __t151 = __t148 - __t149;
            let __t173 = __t170 - __t171;
            let __t220 = __t217 - __t218;
            let __t646 = __t641 * __t45;
            let __t755 = __t754 - __t751;
            let __t854 = __t853 - __t850;
            let __t950 = __t748 * __t50;
            let __t1055 = __t1054 - __t1051;
            let __t1148 = __t847 * __t55;
            let __t2347 = __t2346 - __t2343;
            let __t2393 = __t2392 - __t2389;
            let __t2466 = __t2465 - __t2462;
            let __t645 = __t151 * __t137;
            let __t647 = __t646 * (-2f64);
            let __t764 = __t755 * __t22;
            let __t766 = __t168 * __t18;
            let __t775 = __t138 * __t19;
            let __t776 = __t755 * __t23;
            let __t861 = __t854 * __t22;
            let __t863 = __t199 * __t18;
            let __t875 = __t854 * __t23;
            let __t949 = __t173 * __t137;
            let __t951 = __t950 * (-2f64);
            let __t1064 = __t1055 * __t22;
            let __t1072 = __t1055 * __t23;
            let __t1074 = __t199 * __t19;
            let __t1147 = __t220 * __t137;
            let __t1149 = __t1148 * (-2f64);
            let __t2348 = __t2347 * __t23;
            let __t2367 = __t2347 * __t22;
            let __t2394 = __t2393 * __t23;
            let __t2412 = __t2393 * __t22;
            let __t2467 = __t2466 * __t23;
            let __t2489 = __t2466 * __t22;
            let __t648 = __t647 + __t645;
            let __t656 = __t138 * __t18;
            let __t756 = __t755 * __t24;
            let __t768 = __t766 + __t764;
            let __t777 = __t776 + __t775;
            let __t855 = __t138 * __t20;
            let __t856 = __t854 * __t24;
            let __t865 = __t863 + __t861;
            let __t873 = __t201 * __v2;
            let __t876 = __t140 * __v0;
            let __t877 = __t875 * __t73;
            let __t952 = __t951 + __t949;
            let __t968 = __t168 * __t19;
            let __t1056 = __t168 * __t20;
            let __t1057 = __t1055 * __t24;
            let __t1062 = __t208 * __v2;
            let __t1065 = __t175 * __v1;
            let __t1067 = __t1064 * __t69;
            let __t1076 = __t1074 + __t1072;
            let __t1150 = __t1149 + __t1147;
            let __t2351 = __t2348 + __t775;
            let __t2355 = __t2347 * __t24;
            let __t2368 = __t2367 + __t766;
            let __t2399 = __t2393 * __t24;
            let __t2413 = __t2412 + __t863;
            let __t2418 = __t2394 * __t73;
            let __t2468 = __t2467 + __t1074;
            let __t2472 = __t2466 * __t24;
            let __t2490 = __t2489 * __t69;
            let __t142 = __t140 * __t73;
            let __t177 = __t175 * __t69;
            let __t203 = __t201 * __t73;
            let __t210 = __t208 * __t69;
            let __t212 = __t47 * __v1;
            let __t657 = __t648 * __t22;
            let __t661 = __t656 * 2f64;
            let __t666 = __t140 * __v2;
            let __t668 = __t648 * __t23;
            let __t746 = __t183 * __v1;
            let __t757 = __t154 * __v0;
            let __t759 = __t756 * __t77;
            let __t770 = __t151 * __v2;
            let __t771 = __t768 * __t69;
            let __t774 = __t173 * __v2;
            let __t778 = __t777 * __t73;
            let __t857 = __t856 + __t855;
            let __t867 = __t151 * __v1;
            let __t869 = __t865 * __t69;
            let __t878 = __t877 + __t876;
            let __t959 = __t175 * __v2;
            let __t961 = __t952 * __t22;
            let __t969 = __t952 * __t23;
            let __t973 = __t968 * 2f64;
            let __t1058 = __t1057 + __t1056;
            let __t1068 = __t1067 - __t1065;
            let __t1078 = __t173 * __v0;
            let __t1079 = __t1076 * __t73;
            let __t1151 = __t199 * __t20;
            let __t1161 = __t208 * __v1;
            let __t1163 = __t1150 * __t22;
            let __t1169 = __t201 * __v0;
            let __t1171 = __t1150 * __t23;
            let __t2363 = __t2355 * __t77;
            let __t2369 = __t2368 * __t69;
            let __t2373 = __t2351 * __t73;
            let __t2402 = __t2399 + __t855;
            let __t2414 = __t2413 * __t69;
            let __t2419 = __t2418 - __t873;
            let __t2475 = __t2472 + __t1056;
            let __t2491 = __t2490 + __t1062;
            let __t2494 = __t2468 * __t73;
            let __t78 = __t47 * __t69;
            let __t79 = __t52 * __t73;
            let __t146 = __t142 + __t144;
            let __t152 = __t151 * __t69;
            let __t156 = __t154 * __t77;
            let __t158 = __t57 * __v1;
            let __t174 = __t173 * __t73;
            let __t180 = __t179 - __t177;
            let __t185 = __t183 * __t77;
            let __t187 = __t57 * __v0;
            let __t206 = __t205 - __t203;
            let __t214 = __t212 + __t210;
            let __t252 = __t183 * __v4;
            let __t264 = __t201 * __v5;
            let __t272 = __t154 * __v3;
            let __t292 = __t208 * __v5;
            let __t302 = __t140 * __v3;
            let __t311 = __t175 * __v4;
            let __t638 = __t154 * __v1;
            let __t649 = __t648 * __t24;
            let __t662 = __t661 + __t657;
            let __t669 = __t668 * __t73;
            let __t671 = __t666 * (-2f64);
            let __t760 = __t759 - __t757;
            let __t773 = __t770 - __t771;
            let __t779 = __t778 + __t774;
            let __t792 = __t756 * __v3;
            let __t809 = __t756 * __v4;
            let __t822 = __t777 * __v3;
            let __t826 = __t768 * __v4;
            let __t846 = __t220 * __v1;
            let __t858 = __t857 * __t77;
            let __t871 = __t869 + __t867;
            let __t879 = __t878 - __t873;
            let __t891 = __t865 * __v5;
            let __t895 = __t857 * __v3;
            let __t908 = __t875 * __v5;
            let __t923 = __t875 * __v3;
            let __t947 = __t183 * __v0;
            let __t953 = __t952 * __t24;
            let __t962 = __t961 * __t69;
            let __t965 = __t959 * 2f64;
            let __t974 = __t973 + __t969;
            let __t1050 = __t220 * __v0;
            let __t1059 = __t1058 * __t77;
            let __t1070 = __t1068 + __t1062;
            let __t1081 = __t1078 - __t1079;
            let __t1091 = __t1064 * __v5;
            let __t1105 = __t1076 * __v5;
            let __t1108 = __t1058 * __v4;
            let __t1125 = __t1064 * __v4;
            let __t1152 = __t1150 * __t24;
            let __t1156 = __t1151 * 2f64;
            let __t1164 = __t1163 * __t69;
            let __t1166 = __t1161 * (-2f64);
            let __t1172 = __t1171 * __t73;
            let __t1175 = __t1169 * 2f64;
            let __t2356 = __t2355 * __v4;
            let __t2364 = __t2363 + __t746;
            let __t2371 = __t770 - __t2369;
            let __t2375 = __t2373 + __t774;
            let __t2409 = __t2402 * __t77;
            let __t2415 = __t2414 + __t867;
            let __t2421 = __t2419 + __t876;
            let __t2485 = __t2475 * __t77;
            let __t2492 = __t2491 - __t1065;
            let __t2496 = __t1078 - __t2494;
            let __t2549 = __t2355 * __v3;
            let __t2646 = __t2351 * __v3;
            let __t2650 = __t2368 * __v4;
            let __t80 = __t57 * __t77;
            let __t81 = __t79 + __t78;
            let __t98 = __t52 * __v5;
            let __t100 = __t57 * __v4;
            let __t104 = __t47 * __v5;
            let __t106 = __t57 * __v3;
            let __t109 = __t52 * __v3;
            let __t111 = __t47 * __v4;
            let __t153 = __t152 - __t146;
            let __t159 = __t158 - __t156;
            let __t181 = __t180 + __t174;
            let __t189 = __t187 + __t185;
            let __t216 = __t206 - __t214;
            let __t221 = __t220 * __t77;
            let __t243 = __t154 * __v4;
            let __t245 = __t140 * __v5;
            let __t254 = __t57 - __t252;
            let __t256 = __t173 * __v5;
            let __t262 = __t220 * __v4;
            let __t266 = __t52 - __t264;
            let __t274 = __t57 - __t272;
            let __t275 = __t151 * __v5;
            let __t282 = __t183 * __v3;
            let __t284 = __t175 * __v5;
            let __t291 = __t220 * __v3;
            let __t294 = __t47 - __t292;
            let __t301 = __t151 * __v4;
            let __t304 = __t52 - __t302;
            let __t313 = __t47 - __t311;
            let __t314 = __t173 * __v3;
            let __t321 = __t208 * __v4;
            let __t323 = __t201 * __v3;
            let __t650 = __t649 * __t77;
            let __t653 = __t638 * 2f64;
            let __t664 = __t662 * __t69;
            let __t672 = __t671 + __t669;
            let __t688 = __t649 * __v3;
            let __t691 = __t154 * 2f64;
            let __t719 = __t668 * __v3;
            let __t722 = __t140 * 2f64;
            let __t762 = __t760 + __t746;
            let __t781 = __t773 - __t779;
            let __t790 = __t768 * __v5;
            let __t794 = __t792 + __t183;
            let __t807 = __t777 * __v5;
            let __t810 = __t809 + __t154;
            let __t824 = __t173 - __t822;
            let __t828 = __t151 - __t826;
            let __t860 = __t846 - __t858;
            let __t881 = __t879 + __t871;
            let __t893 = __t151 - __t891;
            let __t897 = __t220 - __t895;
            let __t909 = __t908 + __t140;
            let __t911 = __t857 * __v4;
            let __t925 = __t923 + __t201;
            let __t927 = __t865 * __v4;
            let __t954 = __t953 * __t77;
            let __t956 = __t947 * (-2f64);
            let __t966 = __t965 + __t962;
            let __t976 = __t974 * __t73;
            let __t1006 = __t953 * __v4;
            let __t1009 = __t183 * 2f64;
            let __t1025 = __t961 * __v4;
            let __t1028 = __t175 * 2f64;
            let __t1060 = __t1059 + __t1050;
            let __t1082 = __t1081 - __t1070;
            let __t1092 = __t1091 + __t175;
            let __t1093 = __t1058 * __v3;
            let __t1107 = __t173 - __t1105;
            let __t1110 = __t220 - __t1108;
            let __t1123 = __t1076 * __v3;
            let __t1127 = __t1125 + __t208;
            let __t1157 = __t1156 + __t1152;
            let __t1167 = __t1166 + __t1164;
            let __t1176 = __t1175 + __t1172;
            let __t2353 = __t2351 * __v5;
            let __t2358 = __t2356 + __t154;
            let __t2365 = __t2364 - __t757;
            let __t2377 = __t2371 - __t2375;
            let __t2395 = __t2394 * __v5;
            let __t2411 = __t846 - __t2409;
            let __t2423 = __t2421 + __t2415;
            let __t2469 = __t2468 * __v5;
            let __t2477 = __t2475 * __v4;
            let __t2487 = __t2485 + __t1050;
            let __t2497 = __t2496 - __t2492;
            let __t2548 = __t2368 * __v5;
            let __t2550 = __t2549 + __t183;
            let __t2564 = __t2413 * __v5;
            let __t2568 = __t2402 * __v3;
            let __t2597 = __t2489 * __v5;
            let __t2648 = __t173 - __t2646;
            let __t2652 = __t151 - __t2650;
            let __t2666 = __t2394 * __v3;
            let __t2697 = __t2489 * __v4;
            let __t82 = __t81 + __t80;
            let __t102 = __t98 - __t100;
            let __t107 = __t106 - __t104;
            let __t112 = __t111 - __t109;
            let __t160 = __t159 + __t153;
            let __t191 = __t181 - __t189;
            let __t222 = __t221 + __t216;
            let __t247 = __t243 - __t245;
            let __t257 = __t256 - __t254;
            let __t267 = __t266 - __t262;
            let __t277 = __t274 - __t275;
            let __t286 = __t284 - __t282;
            let __t296 = __t291 - __t294;
            let __t306 = __t301 - __t304;
            let __t316 = __t313 - __t314;
            let __t325 = __t323 - __t321;
            let __t654 = __t653 + __t650;
            let __t674 = __t672 + __t664;
            let __t686 = __t662 * __v5;
            let __t692 = __t691 + __t688;
            let __t704 = __t668 * __v5;
            let __t706 = __t649 * __v4;
            let __t723 = __t722 + __t719;
            let __t725 = __t662 * __v4;
            let __t782 = __t781 - __t762;
            let __t796 = __t790 - __t794;
            let __t811 = __t810 - __t807;
            let __t829 = __t828 - __t824;
            let __t883 = __t860 - __t881;
            let __t898 = __t897 - __t893;
            let __t912 = __t911 - __t909;
            let __t929 = __t925 - __t927;
            let __t957 = __t956 + __t954;
            let __t978 = __t976 + __t966;
            let __t990 = __t961 * __v5;
            let __t991 = __t953 * __v3;
            let __t1004 = __t974 * __v5;
            let __t1010 = __t1009 + __t1006;
            let __t1023 = __t974 * __v3;
            let __t1029 = __t1028 + __t1025;
            let __t1083 = __t1082 - __t1060;
            let __t1095 = __t1092 - __t1093;
            let __t1112 = __t1107 - __t1110;
            let __t1129 = __t1123 - __t1127;
            let __t1159 = __t1157 * __t77;
            let __t1178 = __t1176 + __t1167;
            let __t1190 = __t1163 * __v5;
            let __t1193 = __t208 * 2f64;
            let __t1208 = __t1171 * __v5;
            let __t1211 = __t201 * 2f64;
            let __t2360 = __t2358 - __t2353;
            let __t2378 = __t2377 - __t2365;
            let __t2397 = __t2395 + __t140;
            let __t2404 = __t2402 * __v4;
            let __t2425 = __t2411 - __t2423;
            let __t2471 = __t173 - __t2469;
            let __t2479 = __t220 - __t2477;
            let __t2498 = __t2497 - __t2487;
            let __t2552 = __t2548 - __t2550;
            let __t2566 = __t151 - __t2564;
            let __t2570 = __t220 - __t2568;
            let __t2599 = __t2597 + __t175;
            let __t2601 = __t2475 * __v3;
            let __t2653 = __t2652 - __t2648;
            let __t2667 = __t2666 + __t201;
            let __t2668 = __t2413 * __v4;
            let __t2696 = __t2468 * __v3;
            let __t2698 = __t2697 + __t208;
            let __t676 = __t674 + __t654;
            let __t694 = __t686 - __t692;
            let __t707 = __t706 - __t704;
            let __t727 = __t723 - __t725;
            let __t783 = __t191 * __t160;
            let __t784 = __t782 * __t82;
            let __t797 = __t277 * __t191;
            let __t798 = __t796 * __t82;
            let __t800 = __t286 * __t160;
            let __t801 = __t782 * __t107;
            let __t812 = __t247 * __t191;
            let __t813 = __t811 * __t82;
            let __t815 = __t257 * __t160;
            let __t816 = __t782 * __t102;
            let __t830 = __t306 * __t191;
            let __t831 = __t829 * __t82;
            let __t833 = __t316 * __t160;
            let __t834 = __t782 * __t112;
            let __t884 = __t222 * __t160;
            let __t885 = __t883 * __t82;
            let __t899 = __t277 * __t222;
            let __t900 = __t898 * __t82;
            let __t902 = __t296 * __t160;
            let __t903 = __t883 * __t107;
            let __t913 = __t247 * __t222;
            let __t914 = __t912 * __t82;
            let __t916 = __t267 * __t160;
            let __t917 = __t883 * __t102;
            let __t930 = __t306 * __t222;
            let __t931 = __t929 * __t82;
            let __t933 = __t325 * __t160;
            let __t934 = __t883 * __t112;
            let __t980 = __t978 + __t957;
            let __t993 = __t990 - __t991;
            let __t1012 = __t1010 - __t1004;
            let __t1031 = __t1023 - __t1029;
            let __t1084 = __t222 * __t191;
            let __t1085 = __t1083 * __t82;
            let __t1096 = __t286 * __t222;
            let __t1097 = __t1095 * __t82;
            let __t1099 = __t296 * __t191;
            let __t1100 = __t1083 * __t107;
            let __t1113 = __t257 * __t222;
            let __t1114 = __t1112 * __t82;
            let __t1116 = __t267 * __t191;
            let __t1117 = __t1083 * __t102;
            let __t1130 = __t316 * __t222;
            let __t1131 = __t1129 * __t82;
            let __t1133 = __t325 * __t191;
            let __t1134 = __t1083 * __t112;
            let __t1180 = __t1178 + __t1159;
            let __t1194 = __t1193 + __t1190;
            let __t1196 = __t1157 * __v3;
            let __t1212 = __t1211 + __t1208;
            let __t1214 = __t1157 * __v4;
            let __t1227 = __t1171 * __v3;
            let __t1228 = __t1163 * __v4;
            let __t2361 = __t2360 * __t82;
            let __t2379 = __t2378 * __t102;
            let __t2406 = __t2404 - __t2397;
            let __t2435 = __t2425 * __t82;
            let __t2443 = __t2378 * __t82;
            let __t2481 = __t2471 - __t2479;
            let __t2509 = __t2498 * __t82;
            let __t2553 = __t2552 * __t82;
            let __t2555 = __t2378 * __t107;
            let __t2571 = __t2570 - __t2566;
            let __t2603 = __t2599 - __t2601;
            let __t2654 = __t2653 * __t82;
            let __t2656 = __t2378 * __t112;
            let __t2670 = __t2667 - __t2668;
            let __t2700 = __t2696 - __t2698;
            let __t248 = __t160 * __t102;
            let __t249 = __t247 * __t82;
            let __t258 = __t191 * __t102;
            let __t259 = __t257 * __t82;
            let __t278 = __t160 * __t107;
            let __t279 = __t277 * __t82;
            let __t287 = __t191 * __t107;
            let __t288 = __t286 * __t82;
            let __t307 = __t160 * __t112;
            let __t308 = __t306 * __t82;
            let __t317 = __t191 * __t112;
            let __t318 = __t316 * __t82;
            let __t446 = __t247 * __t107;
            let __t447 = __t277 * __t102;
            let __t452 = __t247 * __t102;
            let __t460 = __t247 * __t112;
            let __t461 = __t306 * __t102;
            let __t471 = __t257 * __t107;
            let __t472 = __t286 * __t102;
            let __t477 = __t257 * __t102;
            let __t484 = __t257 * __t112;
            let __t485 = __t316 * __t102;
            let __t535 = __t277 * __t112;
            let __t536 = __t306 * __t107;
            let __t546 = __t286 * __t107;
            let __t555 = __t286 * __t112;
            let __t556 = __t316 * __t107;
            let __t678 = __t160 * __t160;
            let __t679 = __t676 * __t82;
            let __t695 = __t277 * __t160;
            let __t696 = __t694 * __t82;
            let __t698 = __t676 * __t107;
            let __t708 = __t247 * __t160;
            let __t709 = __t707 * __t82;
            let __t711 = __t676 * __t102;
            let __t728 = __t306 * __t160;
            let __t729 = __t727 * __t82;
            let __t731 = __t676 * __t112;
            let __t785 = __t784 + __t783;
            let __t799 = __t798 + __t797;
            let __t802 = __t801 + __t800;
            let __t814 = __t813 + __t812;
            let __t817 = __t816 + __t815;
            let __t832 = __t831 + __t830;
            let __t835 = __t834 + __t833;
            let __t886 = __t885 + __t884;
            let __t901 = __t900 + __t899;
            let __t904 = __t903 + __t902;
            let __t915 = __t914 + __t913;
            let __t918 = __t917 + __t916;
            let __t932 = __t931 + __t930;
            let __t935 = __t934 + __t933;
            let __t982 = __t191 * __t191;
            let __t983 = __t980 * __t82;
            let __t994 = __t286 * __t191;
            let __t995 = __t993 * __t82;
            let __t997 = __t980 * __t107;
            let __t1013 = __t257 * __t191;
            let __t1014 = __t1012 * __t82;
            let __t1016 = __t980 * __t102;
            let __t1032 = __t316 * __t191;
            let __t1033 = __t1031 * __t82;
            let __t1035 = __t980 * __t112;
            let __t1086 = __t1085 + __t1084;
            let __t1098 = __t1097 + __t1096;
            let __t1101 = __t1100 + __t1099;
            let __t1115 = __t1114 + __t1113;
            let __t1118 = __t1117 + __t1116;
            let __t1132 = __t1131 + __t1130;
            let __t1135 = __t1134 + __t1133;
            let __t1182 = __t222 * __t222;
            let __t1183 = __t1180 * __t82;
            let __t1198 = __t1194 - __t1196;
            let __t1216 = __t1214 - __t1212;
            let __t1230 = __t1227 - __t1228;
            let __t2362 = __t2361 + __t815;
            let __t2380 = __t2379 + __t812;
            let __t2407 = __t2406 * __t82;
            let __t2426 = __t2425 * __t102;
            let __t2436 = __t2435 + __t884;
            let __t2444 = __t2443 + __t783;
            let __t2482 = __t2481 * __t82;
            let __t2499 = __t2498 * __t102;
            let __t2510 = __t2509 + __t1084;
            let __t2554 = __t2553 + __t800;
            let __t2556 = __t2555 + __t797;
            let __t2572 = __t2571 * __t82;
            let __t2574 = __t2425 * __t107;
            let __t2604 = __t2603 * __t82;
            let __t2606 = __t2498 * __t107;
            let __t2655 = __t2654 + __t833;
            let __t2657 = __t2656 + __t830;
            let __t2671 = __t2670 * __t82;
            let __t2673 = __t2425 * __t112;
            let __t2701 = __t2700 * __t82;
            let __t2703 = __t2498 * __t112;
            let __t116 = __t102 * __t82;
            let __t122 = __t107 * __t82;
            let __t128 = __t112 * __t82;
            let __t161 = __t160 * __t82;
            let __t192 = __t191 * __t82;
            let __t223 = __t222 * __t82;
            let __t228 = __t102 * __t102;
            let __t231 = __t107 * __t102;
            let __t233 = __t112 * __t102;
            let __t235 = __t107 * __t107;
            let __t238 = __t112 * __t107;
            let __t240 = __t112 * __t112;
            let __t250 = __t249 + __t248;
            let __t260 = __t259 + __t258;
            let __t268 = __t222 * __t102;
            let __t269 = __t267 * __t82;
            let __t280 = __t279 + __t278;
            let __t289 = __t288 + __t287;
            let __t297 = __t222 * __t107;
            let __t298 = __t296 * __t82;
            let __t309 = __t308 + __t307;
            let __t319 = __t318 + __t317;
            let __t326 = __t222 * __t112;
            let __t327 = __t325 * __t82;
            let __t448 = __t447 + __t446;
            let __t454 = __t452 * __v16;
            let __t462 = __t461 + __t460;
            let __t473 = __t472 + __t471;
            let __t479 = __t477 * __v16;
            let __t486 = __t485 + __t484;
            let __t495 = __t267 * __t107;
            let __t496 = __t296 * __t102;
            let __t500 = __t267 * __t102;
            let __t507 = __t267 * __t112;
            let __t508 = __t325 * __t102;
            let __t526 = __t277 * __t107;
            let __t537 = __t536 + __t535;
            let __t548 = __t546 * __v16;
            let __t557 = __t556 + __t555;
            let __t574 = __t296 * __t112;
            let __t575 = __t325 * __t107;
            let __t610 = __t316 * __t112;
            let __t681 = __t678 - __t679;
            let __t697 = __t696 + __t695;
            let __t700 = __t695 - __t698;
            let __t710 = __t709 + __t708;
            let __t713 = __t708 - __t711;
            let __t730 = __t729 + __t728;
            let __t733 = __t728 - __t731;
            let __t786 = __t785 * __v16;
            let __t787 = __t175 * __t87;
            let __t803 = __t802 + __t799;
            let __t818 = __t817 + __t814;
            let __t836 = __t835 + __t832;
            let __t887 = __t886 * __v16;
            let __t888 = __t208 * __t87;
            let __t905 = __t904 + __t901;
            let __t919 = __t918 + __t915;
            let __t936 = __t935 + __t932;
            let __t985 = __t982 - __t983;
            let __t996 = __t995 + __t994;
            let __t999 = __t994 - __t997;
            let __t1015 = __t1014 + __t1013;
            let __t1018 = __t1013 - __t1016;
            let __t1034 = __t1033 + __t1032;
            let __t1037 = __t1032 - __t1035;
            let __t1087 = __t1086 * __v16;
            let __t1088 = __t201 * __t87;
            let __t1102 = __t1101 + __t1098;
            let __t1119 = __t1118 + __t1115;
            let __t1136 = __t1135 + __t1132;
            let __t1185 = __t1182 - __t1183;
            let __t1199 = __t296 * __t222;
            let __t1200 = __t1198 * __t82;
            let __t1202 = __t1180 * __t107;
            let __t1217 = __t267 * __t222;
            let __t1218 = __t1216 * __t82;
            let __t1220 = __t1180 * __t102;
            let __t1231 = __t325 * __t222;
            let __t1232 = __t1230 * __t82;
            let __t1234 = __t1180 * __t112;
            let __t2381 = __t2380 + __t2362;
            let __t2408 = __t2407 + __t916;
            let __t2427 = __t2426 + __t913;
            let __t2437 = __t2436 * __v16;
            let __t2438 = __t154 * __t87;
            let __t2445 = __t2444 * __v16;
            let __t2446 = __t140 * __t87;
            let __t2483 = __t2482 + __t1116;
            let __t2500 = __t2499 + __t1113;
            let __t2511 = __t2510 * __v16;
            let __t2512 = __t183 * __t87;
            let __t2557 = __t2556 + __t2554;
            let __t2573 = __t2572 + __t902;
            let __t2575 = __t2574 + __t899;
            let __t2605 = __t2604 + __t1099;
            let __t2607 = __t2606 + __t1096;
            let __t2658 = __t2657 + __t2655;
            let __t2672 = __t2671 + __t933;
            let __t2674 = __t2673 + __t930;
            let __t2702 = __t2701 + __t1133;
            let __t2704 = __t2703 + __t1130;
            let __t118 = __t116 * __v16;
            let __t124 = __t122 * __v16;
            let __t130 = __t128 * __v16;
            let __t134 = __t47 * __t87;
            let __t163 = __t161 * __v16;
            let __t166 = __t52 * __t87;
            let __t194 = __t192 * __v16;
            let __t197 = __t57 * __t87;
            let __t225 = __t223 * __v16;
            let __t229 = __t228 * __v16;
            let __t232 = __t231 * __v16;
            let __t234 = __t233 * __v16;
            let __t236 = __t235 * __v16;
            let __t239 = __t238 * __v16;
            let __t241 = __t240 * __v16;
            let __t251 = __t250 * __v16;
            let __t261 = __t260 * __v16;
            let __t270 = __t269 + __t268;
            let __t281 = __t280 * __v16;
            let __t290 = __t289 * __v16;
            let __t299 = __t298 + __t297;
            let __t310 = __t309 * __v16;
            let __t320 = __t319 * __v16;
            let __t328 = __t327 + __t326;
            let __t449 = __t448 * __v16;
            let __t463 = __t462 * __v16;
            let __t474 = __t473 * __v16;
            let __t487 = __t486 * __v16;
            let __t497 = __t496 + __t495;
            let __t502 = __t500 * __v16;
            let __t509 = __t508 + __t507;
            let __t528 = __t526 * __v16;
            let __t538 = __t537 * __v16;
            let __t558 = __t557 * __v16;
            let __t566 = __t296 * __t107;
            let __t576 = __t575 + __t574;
            let __t594 = __t306 * __t112;
            let __t612 = __t610 * __v16;
            let __t682 = __t681 * __v16;
            let __t683 = __t151 * __t87;
            let __t701 = __t700 + __t697;
            let __t714 = __t713 + __t710;
            let __t734 = __t733 + __t730;
            let __t789 = __t787 + __t786;
            let __t804 = __t803 * __v16;
            let __t819 = __t818 * __v16;
            let __t837 = __t836 * __v16;
            let __t890 = __t888 + __t887;
            let __t906 = __t905 * __v16;
            let __t920 = __t919 * __v16;
            let __t937 = __t936 * __v16;
            let __t986 = __t985 * __v16;
            let __t987 = __t173 * __t87;
            let __t1000 = __t999 + __t996;
            let __t1019 = __t1018 + __t1015;
            let __t1038 = __t1037 + __t1034;
            let __t1090 = __t1088 + __t1087;
            let __t1103 = __t1102 * __v16;
            let __t1120 = __t1119 * __v16;
            let __t1137 = __t1136 * __v16;
            let __t1186 = __t1185 * __v16;
            let __t1187 = __t220 * __t87;
            let __t1201 = __t1200 + __t1199;
            let __t1204 = __t1199 - __t1202;
            let __t1219 = __t1218 + __t1217;
            let __t1222 = __t1217 - __t1220;
            let __t1233 = __t1232 + __t1231;
            let __t1236 = __t1231 - __t1234;
            let __t2167 = __t479 * __t73;
            let __t2170 = __t454 * __t69;
            let __t2247 = __t548 * __t73;
            let __t2382 = __t2381 * __v16;
            let __t2428 = __t2427 + __t2408;
            let __t2440 = __t2438 + __t2437;
            let __t2448 = __t2446 + __t2445;
            let __t2501 = __t2500 + __t2483;
            let __t2514 = __t2512 + __t2511;
            let __t2558 = __t2557 * __v16;
            let __t2576 = __t2575 + __t2573;
            let __t2608 = __t2607 + __t2605;
            let __t2659 = __t2658 * __v16;
            let __t2675 = __t2674 + __t2672;
            let __t2705 = __t2704 + __t2702;
            let __t121 = __t118 + __t58;
            let __t127 = __t124 + __t59;
            let __t133 = __t130 + __t60;
            let __t165 = __t163 - __t134;
            let __t196 = __t194 - __t166;
            let __t227 = __t225 - __t197;
            let __t230 = __t229 + __v7;
            let __t237 = __t236 + __v8;
            let __t242 = __t241 + __v9;
            let __t271 = __t270 * __v16;
            let __t300 = __t299 * __v16;
            let __t329 = __t328 * __v16;
            let __t387 = __t281 * __v4;
            let __t388 = __t310 * __v5;
            let __t392 = __t261 * __v3;
            let __t394 = __t320 * __v5;
            let __t498 = __t497 * __v16;
            let __t510 = __t509 * __v16;
            let __t568 = __t566 * __v16;
            let __t577 = __t576 * __v16;
            let __t596 = __t594 * __v16;
            let __t625 = __t325 * __t112;
            let __t685 = __t682 - __t683;
            let __t702 = __t701 * __v16;
            let __t715 = __t714 * __v16;
            let __t735 = __t734 * __v16;
            let __t989 = __t986 - __t987;
            let __t1001 = __t1000 * __v16;
            let __t1020 = __t1019 * __v16;
            let __t1039 = __t1038 * __v16;
            let __t1189 = __t1186 - __t1187;
            let __t1205 = __t1204 + __t1201;
            let __t1223 = __t1222 + __t1219;
            let __t1237 = __t1236 + __t1233;
            let __t2175 = __t502 * __t77;
            let __t2181 = __t234 * __v1;
            let __t2183 = __t232 * __v2;
            let __t2186 = __t2167 * (-2f64);
            let __t2187 = __t2170 * (-2f64);
            let __t2194 = __t474 * __t73;
            let __t2195 = __t251 * __v5;
            let __t2197 = __t449 * __t69;
            let __t2205 = __t290 * __v5;
            let __t2207 = __t239 * __v1;
            let __t2215 = __t487 * __t73;
            let __t2217 = __t251 * __v4;
            let __t2218 = __t463 * __t69;
            let __t2229 = __t239 * __v2;
            let __t2242 = __t234 * __v0;
            let __t2251 = __t528 * __t69;
            let __t2263 = __t239 * __v0;
            let __t2266 = __t2247 * (-2f64);
            let __t2273 = __t290 * __v3;
            let __t2275 = __t558 * __t73;
            let __t2277 = __t538 * __t69;
            let __t2286 = __t234 * __v2;
            let __t2299 = __t232 * __v0;
            let __t2314 = __t232 * __v1;
            let __t2321 = __t612 * __t73;
            let __t2383 = __t261 * __v2;
            let __t2385 = __t2382 * __t73;
            let __t2429 = __t2428 * __v16;
            let __t2451 = __t310 * __v1;
            let __t2453 = __t281 * __v2;
            let __t2458 = __t251 * __v2;
            let __t2459 = __t819 * __t69;
            let __t2502 = __t2501 * __v16;
            let __t2515 = __t2514 * __v4;
            let __t2522 = __t290 * __v2;
            let __t2526 = __t261 * __v0;
            let __t2527 = __t1120 * __t73;
            let __t2529 = __t251 * __v1;
            let __t2531 = __t920 * __t69;
            let __t2539 = __t1090 * __v5;
            let __t2560 = __t2558 * __t73;
            let __t2577 = __t2576 * __v16;
            let __t2585 = __t2440 * __v3;
            let __t2594 = __t804 * __t69;
            let __t2609 = __t2608 * __v16;
            let __t2620 = __t320 * __v0;
            let __t2624 = __t290 * __v0;
            let __t2625 = __t1103 * __t73;
            let __t2627 = __t281 * __v1;
            let __t2629 = __t906 * __t69;
            let __t2635 = __t890 * __v5;
            let __t2660 = __t320 * __v2;
            let __t2662 = __t2659 * __t73;
            let __t2676 = __t2675 * __v16;
            let __t2681 = __t2448 * __v3;
            let __t2692 = __t310 * __v2;
            let __t2693 = __t837 * __t69;
            let __t2706 = __t2705 * __v16;
            let __t2714 = __t789 * __v4;
            let __t2722 = __t1137 * __t73;
            let __t2724 = __t937 * __t69;
            let __t398 = __t271 * __v3;
            let __t399 = __t300 * __v4;
            let __t627 = __t625 * __v16;
            let __t1206 = __t1205 * __v16;
            let __t1224 = __t1223 * __v16;
            let __t1238 = __t1237 * __v16;
            let __t2070 = __t251 * __t69;
            let __t2071 = __t261 * __t73;
            let __t2075 = __t281 * __t69;
            let __t2076 = __t290 * __t73;
            let __t2080 = __t310 * __t69;
            let __t2081 = __t320 * __t73;
            let __t2085 = __t127 * __v2;
            let __t2086 = __t133 * __v1;
            let __t2089 = __t133 * __v0;
            let __t2090 = __t121 * __v2;
            let __t2093 = __t121 * __v1;
            let __t2094 = __t127 * __v0;
            let __t2097 = __t196 * __v5;
            let __t2098 = __t227 * __v4;
            let __t2101 = __t227 * __v3;
            let __t2102 = __t165 * __v5;
            let __t2105 = __t165 * __v4;
            let __t2106 = __t196 * __v3;
            let __t2188 = __t2187 + __t2186;
            let __t2189 = __t2175 * (-2f64);
            let __t2198 = __t2197 - __t2195;
            let __t2200 = __t498 * __t77;
            let __t2208 = __t2207 + __t133;
            let __t2210 = __t237 * __v2;
            let __t2216 = __t2215 - __t392;
            let __t2219 = __t2218 + __t2217;
            let __t2221 = __t510 * __t77;
            let __t2224 = __t329 * __v4;
            let __t2227 = __t242 * __v1;
            let __t2230 = __t2229 + __t127;
            let __t2234 = __t2205 + __t2194;
            let __t2240 = __t230 * __v2;
            let __t2243 = __t2242 + __t133;
            let __t2256 = __t568 * __t77;
            let __t2267 = __t2266 - __t2183;
            let __t2268 = __t2251 * (-2f64);
            let __t2276 = __t2275 - __t2273;
            let __t2278 = __t2277 + __t387;
            let __t2280 = __t577 * __t77;
            let __t2284 = __t329 * __v3;
            let __t2287 = __t2286 + __t121;
            let __t2289 = __t242 * __v0;
            let __t2293 = __t2215 + __t394;
            let __t2300 = __t2299 + __t127;
            let __t2302 = __t230 * __v1;
            let __t2306 = __t2277 - __t388;
            let __t2312 = __t237 * __v0;
            let __t2315 = __t2314 + __t121;
            let __t2325 = __t596 * __t69;
            let __t2335 = __t2181 - __t2263;
            let __t2337 = __t2321 * (-2f64);
            let __t2386 = __t2385 - __t2383;
            let __t2387 = __t715 * __t69;
            let __t2430 = __t271 * __v1;
            let __t2431 = __t2429 * __t77;
            let __t2441 = __t2440 * __v4;
            let __t2449 = __t2448 * __v5;
            let __t2457 = __t1020 * __t73;
            let __t2460 = __t2459 + __t2458;
            let __t2503 = __t271 * __v0;
            let __t2505 = __t2502 * __t77;
            let __t2516 = __t2515 + __t227;
            let __t2518 = __t989 * __v5;
            let __t2520 = __t320 * __v1;
            let __t2528 = __t2527 + __t2526;
            let __t2532 = __t2531 - __t2529;
            let __t2537 = __t1189 * __v4;
            let __t2540 = __t2539 + __t196;
            let __t2542 = __t329 * __v1;
            let __t2544 = __t300 * __v2;
            let __t2561 = __t2560 - __t2522;
            let __t2562 = __t702 * __t69;
            let __t2578 = __t300 * __v1;
            let __t2579 = __t2577 * __t77;
            let __t2583 = __t685 * __v5;
            let __t2586 = __t2585 + __t227;
            let __t2589 = __t310 * __v0;
            let __t2593 = __t1001 * __t73;
            let __t2595 = __t2594 + __t2453;
            let __t2610 = __t300 * __v0;
            let __t2612 = __t2609 * __t77;
            let __t2616 = __t789 * __v5;
            let __t2618 = __t2514 * __v3;
            let __t2626 = __t2625 + __t2624;
            let __t2630 = __t2629 - __t2627;
            let __t2636 = __t2635 + __t165;
            let __t2638 = __t1189 * __v3;
            let __t2640 = __t271 * __v2;
            let __t2642 = __t329 * __v0;
            let __t2663 = __t2662 - __t2660;
            let __t2664 = __t735 * __t69;
            let __t2677 = __t2676 * __t77;
            let __t2682 = __t2681 + __t196;
            let __t2684 = __t685 * __v4;
            let __t2686 = __t281 * __v0;
            let __t2691 = __t1039 * __t73;
            let __t2694 = __t2693 + __t2692;
            let __t2708 = __t2706 * __t77;
            let __t2712 = __t989 * __v3;
            let __t2715 = __t2714 + __t165;
            let __t2718 = __t261 * __v1;
            let __t2723 = __t2722 + __t2620;
            let __t2725 = __t2724 - __t2451;
            let __t2730 = __t1090 * __v3;
            let __t2732 = __t890 * __v4;
            let __t2072 = __t271 * __t77;
            let __t2073 = __t2071 + __t2070;
            let __t2077 = __t300 * __t77;
            let __t2078 = __t2076 + __t2075;
            let __t2082 = __t329 * __t77;
            let __t2083 = __t2081 + __t2080;
            let __t2088 = __t2085 - __t2086;
            let __t2092 = __t2089 - __t2090;
            let __t2096 = __t2093 - __t2094;
            let __t2100 = __t2097 - __t2098;
            let __t2104 = __t2101 - __t2102;
            let __t2108 = __t2105 - __t2106;
            let __t2190 = __t2189 + __t2188;
            let __t2199 = __t2198 + __t2194;
            let __t2201 = __t2200 + __t398;
            let __t2206 = __t2205 - __t399;
            let __t2211 = __t2210 - __t2208;
            let __t2220 = __t2219 + __t2216;
            let __t2226 = __t394 - __t2224;
            let __t2231 = __t2230 - __t2227;
            let __t2235 = __t2234 + __t2197;
            let __t2236 = __t2200 - __t399;
            let __t2239 = __t398 - __t2195;
            let __t2244 = __t2243 - __t2240;
            let __t2269 = __t2268 + __t2267;
            let __t2270 = __t2256 * (-2f64);
            let __t2279 = __t2278 + __t2276;
            let __t2285 = __t2284 - __t388;
            let __t2290 = __t2289 - __t2287;
            let __t2294 = __t2293 + __t2218;
            let __t2295 = __t2221 - __t2224;
            let __t2298 = __t2217 - __t392;
            let __t2303 = __t2302 - __t2300;
            let __t2307 = __t2306 + __t2275;
            let __t2308 = __t2284 + __t2280;
            let __t2311 = __t387 - __t2273;
            let __t2316 = __t2315 - __t2312;
            let __t2329 = __t627 * __t77;
            let __t2338 = __t2337 + __t2335;
            let __t2339 = __t2325 * (-2f64);
            let __t2388 = __t2387 + __t2386;
            let __t2432 = __t2431 + __t2430;
            let __t2450 = __t2449 - __t2441;
            let __t2454 = __t2453 - __t2451;
            let __t2461 = __t2460 + __t2457;
            let __t2506 = __t2505 - __t2503;
            let __t2519 = __t2518 - __t2516;
            let __t2523 = __t2522 - __t2520;
            let __t2533 = __t2532 + __t2528;
            let __t2534 = __t1224 * __t77;
            let __t2541 = __t2540 - __t2537;
            let __t2545 = __t2544 - __t2542;
            let __t2563 = __t2562 + __t2561;
            let __t2580 = __t2579 + __t2578;
            let __t2587 = __t2586 - __t2583;
            let __t2590 = __t2589 - __t2458;
            let __t2596 = __t2595 + __t2593;
            let __t2613 = __t2612 - __t2610;
            let __t2619 = __t2618 - __t2616;
            let __t2621 = __t2620 - __t2383;
            let __t2631 = __t2630 + __t2626;
            let __t2632 = __t1206 * __t77;
            let __t2639 = __t2638 - __t2636;
            let __t2643 = __t2642 - __t2640;
            let __t2665 = __t2664 + __t2663;
            let __t2678 = __t2677 + __t2542;
            let __t2685 = __t2684 - __t2682;
            let __t2688 = __t2529 - __t2686;
            let __t2695 = __t2694 + __t2691;
            let __t2709 = __t2708 - __t2642;
            let __t2716 = __t2715 - __t2712;
            let __t2719 = __t2718 - __t2624;
            let __t2726 = __t2725 + __t2723;
            let __t2727 = __t1238 * __t77;
            let __t2733 = __t2732 - __t2730;
            let __t2734 = __t2430 - __t2610;
            let __t2074 = __t2073 + __t2072;
            let __t2079 = __t2078 + __t2077;
            let __t2084 = __t2083 + __t2082;
            let __t2109 = __t2100 + __t2088;
            let __t2112 = __t2104 + __t2092;
            let __t2115 = __t2108 + __t2096;
            let __t2192 = __t2190 - __t2181;
            let __t2202 = __t2201 + __t2199;
            let __t2212 = __t2211 + __t2206;
            let __t2222 = __t2220 + __t2221;
            let __t2232 = __t2231 + __t2226;
            let __t2237 = __t2236 + __t2235;
            let __t2245 = __t2244 + __t2239;
            let __t2271 = __t2270 + __t2269;
            let __t2281 = __t2279 + __t2280;
            let __t2291 = __t2290 + __t2285;
            let __t2296 = __t2295 + __t2294;
            let __t2304 = __t2303 + __t2298;
            let __t2309 = __t2308 + __t2307;
            let __t2317 = __t2316 + __t2311;
            let __t2340 = __t2339 + __t2338;
            let __t2341 = __t2329 * (-2f64);
            let __t2433 = __t2432 + __t2388;
            let __t2455 = __t2454 + __t2450;
            let __t2507 = __t2506 + __t2461;
            let __t2524 = __t2523 + __t2519;
            let __t2535 = __t2534 + __t2533;
            let __t2546 = __t2545 + __t2541;
            let __t2581 = __t2580 + __t2563;
            let __t2591 = __t2590 + __t2587;
            let __t2614 = __t2613 + __t2596;
            let __t2622 = __t2621 + __t2619;
            let __t2633 = __t2632 + __t2631;
            let __t2644 = __t2643 + __t2639;
            let __t2679 = __t2678 + __t2665;
            let __t2689 = __t2688 + __t2685;
            let __t2710 = __t2709 + __t2695;
            let __t2720 = __t2719 + __t2716;
            let __t2728 = __t2727 + __t2726;
            let __t2735 = __t2734 + __t2733;
            let __t455 = __t454 * 2f64;
            let __t480 = __t479 * 2f64;
            let __t503 = __t502 * 2f64;
            let __t529 = __t528 * 2f64;
            let __t549 = __t548 * 2f64;
            let __t569 = __t568 * 2f64;
            let __t597 = __t596 * 2f64;
            let __t613 = __t612 * 2f64;
            let __t628 = __t627 * 2f64;
            let __t2111 = __t2109 - __t2074;
            let __t2114 = __t2112 - __t2079;
            let __t2117 = __t2115 - __t2084;
            let __t2193 = __t2192 + __t2183;
            let __t2213 = __t2212 - __t2202;
            let __t2233 = __t2232 - __t2222;
            let __t2246 = __t2245 - __t2237;
            let __t2272 = __t2271 + __t2263;
            let __t2292 = __t2291 - __t2281;
            let __t2305 = __t2304 - __t2296;
            let __t2318 = __t2317 - __t2309;
            let __t2342 = __t2341 + __t2340;
            let __t2456 = __t2455 - __t2433;
            let __t2525 = __t2524 - __t2507;
            let __t2547 = __t2546 - __t2535;
            let __t2592 = __t2591 - __t2581;
            let __t2623 = __t2622 - __t2614;
            let __t2645 = __t2644 - __t2633;
            let __t2690 = __t2689 - __t2679;
            let __t2721 = __t2720 - __t2710;
            let __t2736 = __t2735 - __t2728;
            __FullJacobian {
                inertia: __Matrix3::new(
                    __t230,
                    __t232,
                    __t234,
                    __t232,
                    __t237,
                    __t239,
                    __t234,
                    __t239,
                    __t242,
                ),
                right_side: __Vector3::new(__t2111, __t2114, __t2117),
                dright_domega: __Matrix3::new(
                    __t2193,
                    __t2213,
                    __t2233,
                    __t2246,
                    __t2272,
                    __t2292,
                    __t2305,
                    __t2318,
                    __t2342,
                ),
                dright_dgamma: __Matrix3::new(
                    __t2456,
                    __t2525,
                    __t2547,
                    __t2592,
                    __t2623,
                    __t2645,
                    __t2690,
                    __t2721,
                    __t2736,
                ),
                dinertia_dgamma: [
                    __Matrix3::new(
                        __t455,
                        __t449,
                        __t463,
                        __t449,
                        __t529,
                        __t538,
                        __t463,
                        __t538,
                        __t597,
                    ),
                    __Matrix3::new(
                        __t480,
                        __t474,
                        __t487,
                        __t474,
                        __t549,
                        __t558,
                        __t487,
                        __t558,
                        __t613,
                    ),
                    __Matrix3::new(
                        __t503,
                        __t498,
                        __t510,
                        __t498,
                        __t569,
                        __t577,
                        __t510,
                        __t577,
                        __t628,
                    ),
                ],
            }
        }
        #[inline]
        fn flow_tape(&self) -> __MaybeFlowTape {
            static __FLOW_OPS: [__Op; 270] = [
                __Op::Omega(0),
                __Op::Omega(1),
                __Op::Omega(2),
                __Op::Gamma(0),
                __Op::Gamma(1),
                __Op::Gamma(2),
                __Op::Param(0),
                __Op::Param(1),
                __Op::Param(2),
                __Op::Param(3),
                __Op::Param(4),
                __Op::Param(5),
                __Op::Param(6),
                __Op::Param(7),
                __Op::Param(8),
                __Op::Param(9),
                __Op::Param(10),
                __Op::Powi(9, 2),
                __Op::Powi(10, 2),
                __Op::Powi(11, 2),
                __Op::Mul(3, 17),
                __Op::Mul(4, 18),
                __Op::Mul(5, 19),
                __Op::Mul(3, 20),
                __Op::Mul(4, 21),
                __Op::Mul(5, 22),
                __Op::Add(23, 24),
                __Op::Add(25, 26),
                __Op::Func(__Func::Sqrt, 27),
                __Op::Mul(3, 12),
                __Op::Mul(4, 13),
                __Op::Mul(5, 14),
                __Op::Add(29, 30),
                __Op::Add(31, 32),
                __Op::Neg(33),
                __Op::Add(28, 34),
                __Op::Neg(12),
                __Op::Const(0x3fe0000000000000),
                __Op::Recip(28),
                __Op::Mul(20, 38),
                __Op::Add(36, 39),
                __Op::Neg(13),
                __Op::Mul(21, 38),
                __Op::Add(41, 42),
                __Op::Neg(14),
                __Op::Mul(22, 38),
                __Op::Add(44, 45),
                __Op::Mul(0, 6),
                __Op::Mul(1, 7),
                __Op::Mul(2, 8),
                __Op::Mul(0, 47),
                __Op::Mul(1, 48),
                __Op::Mul(2, 49),
                __Op::Add(50, 51),
                __Op::Add(52, 53),
                __Op::Mul(2, 4),
                __Op::Mul(1, 5),
                __Op::Neg(56),
                __Op::Add(55, 57),
                __Op::Mul(0, 5),
                __Op::Mul(2, 3),
                __Op::Neg(60),
                __Op::Add(59, 61),
                __Op::Mul(1, 3),
                __Op::Mul(0, 4),
                __Op::Neg(64),
                __Op::Add(63, 65),
                __Op::Mul(40, 58),
                __Op::Mul(43, 62),
                __Op::Mul(46, 66),
                __Op::Add(67, 68),
                __Op::Add(69, 70),
                __Op::Powi(71, 2),
                __Op::Mul(15, 72),
                __Op::Add(54, 73),
                __Op::Mul(37, 74),
                __Op::Mul(15, 16),
                __Op::Mul(35, 76),
                __Op::Mul(5, 43),
                __Op::Mul(4, 46),
                __Op::Neg(79),
                __Op::Add(78, 80),
                __Op::Mul(5, 40),
                __Op::Neg(82),
                __Op::Mul(3, 46),
                __Op::Add(83, 84),
                __Op::Mul(3, 43),
                __Op::Neg(86),
                __Op::Mul(4, 40),
                __Op::Add(87, 88),
                __Op::Neg(77),
                __Op::Add(75, 90),
                __Op::Mul(71, 81),
                __Op::Mul(15, 92),
                __Op::Add(47, 93),
                __Op::Mul(71, 85),
                __Op::Mul(15, 95),
                __Op::Add(48, 96),
                __Op::Mul(71, 89),
                __Op::Mul(15, 98),
                __Op::Add(49, 99),
                __Op::Mul(40, 76),
                __Op::Neg(101),
                __Op::Powi(38, 2),
                __Op::Mul(39, 103),
                __Op::Mul(21, 104),
                __Op::Mul(62, 105),
                __Op::Mul(2, 43),
                __Op::Add(106, 107),
                __Op::Neg(108),
                __Op::Mul(17, 38),
                __Op::Mul(20, 104),
                __Op::Neg(111),
                __Op::Add(110, 112),
                __Op::Mul(58, 113),
                __Op::Add(109, 114),
                __Op::Mul(22, 104),
                __Op::Mul(66, 116),
                __Op::Neg(117),
                __Op::Mul(1, 46),
                __Op::Add(118, 119),
                __Op::Add(115, 120),
                __Op::Mul(71, 121),
                __Op::Mul(15, 122),
                __Op::Add(102, 123),
                __Op::Mul(43, 76),
                __Op::Neg(125),
                __Op::Mul(42, 103),
                __Op::Mul(18, 38),
                __Op::Mul(21, 127),
                __Op::Neg(129),
                __Op::Add(128, 130),
                __Op::Mul(62, 131),
                __Op::Mul(20, 127),
                __Op::Mul(58, 133),
                __Op::Neg(134),
                __Op::Mul(2, 40),
                __Op::Add(135, 136),
                __Op::Add(132, 137),
                __Op::Mul(22, 127),
                __Op::Mul(66, 139),
                __Op::Mul(0, 46),
                __Op::Add(140, 141),
                __Op::Neg(142),
                __Op::Add(138, 143),
                __Op::Mul(71, 144),
                __Op::Mul(15, 145),
                __Op::Add(126, 146),
                __Op::Mul(46, 76),
                __Op::Neg(148),
                __Op::Mul(45, 103),
                __Op::Mul(21, 150),
                __Op::Mul(62, 151),
                __Op::Neg(152),
                __Op::Mul(0, 43),
                __Op::Add(153, 154),
                __Op::Mul(20, 150),
                __Op::Mul(58, 156),
                __Op::Mul(1, 40),
                __Op::Add(157, 158),
                __Op::Neg(159),
                __Op::Add(155, 160),
                __Op::Mul(19, 38),
                __Op::Mul(22, 150),
                __Op::Neg(163),
                __Op::Add(162, 164),
                __Op::Mul(66, 165),
                __Op::Add(161, 166),
                __Op::Mul(71, 167),
                __Op::Mul(15, 168),
                __Op::Add(149, 169),
                __Op::Powi(81, 2),
                __Op::Mul(15, 171),
                __Op::Add(6, 172),
                __Op::Mul(81, 85),
                __Op::Mul(15, 174),
                __Op::Mul(81, 89),
                __Op::Mul(15, 176),
                __Op::Powi(85, 2),
                __Op::Mul(15, 178),
                __Op::Add(7, 179),
                __Op::Mul(85, 89),
                __Op::Mul(15, 181),
                __Op::Powi(89, 2),
                __Op::Mul(15, 183),
                __Op::Add(8, 184),
                __Op::Mul(4, 116),
                __Op::Mul(5, 105),
                __Op::Neg(187),
                __Op::Add(186, 188),
                __Op::Mul(81, 121),
                __Op::Mul(71, 189),
                __Op::Add(190, 191),
                __Op::Mul(15, 192),
                __Op::Mul(4, 139),
                __Op::Neg(194),
                __Op::Add(46, 195),
                __Op::Neg(196),
                __Op::Mul(5, 131),
                __Op::Add(197, 198),
                __Op::Mul(81, 144),
                __Op::Mul(71, 199),
                __Op::Add(200, 201),
                __Op::Mul(15, 202),
                __Op::Mul(4, 165),
                __Op::Neg(204),
                __Op::Mul(5, 151),
                __Op::Neg(206),
                __Op::Add(43, 207),
                __Op::Add(205, 208),
                __Op::Mul(81, 167),
                __Op::Mul(71, 209),
                __Op::Add(210, 211),
                __Op::Mul(15, 212),
                __Op::Mul(3, 116),
                __Op::Neg(214),
                __Op::Add(46, 215),
                __Op::Mul(5, 113),
                __Op::Neg(217),
                __Op::Add(216, 218),
                __Op::Mul(85, 121),
                __Op::Mul(71, 219),
                __Op::Add(220, 221),
                __Op::Mul(15, 222),
                __Op::Mul(3, 139),
                __Op::Neg(224),
                __Op::Mul(5, 133),
                __Op::Add(225, 226),
                __Op::Mul(85, 144),
                __Op::Mul(71, 227),
                __Op::Add(228, 229),
                __Op::Mul(15, 230),
                __Op::Mul(3, 165),
                __Op::Mul(5, 156),
                __Op::Neg(233),
                __Op::Add(40, 234),
                __Op::Neg(235),
                __Op::Add(232, 236),
                __Op::Mul(85, 167),
                __Op::Mul(71, 237),
                __Op::Add(238, 239),
                __Op::Mul(15, 240),
                __Op::Mul(4, 113),
                __Op::Mul(3, 105),
                __Op::Neg(243),
                __Op::Add(43, 244),
                __Op::Neg(245),
                __Op::Add(242, 246),
                __Op::Mul(89, 121),
                __Op::Mul(71, 247),
                __Op::Add(248, 249),
                __Op::Mul(15, 250),
                __Op::Mul(4, 133),
                __Op::Neg(252),
                __Op::Add(40, 253),
                __Op::Mul(3, 131),
                __Op::Neg(255),
                __Op::Add(254, 256),
                __Op::Mul(89, 144),
                __Op::Mul(71, 257),
                __Op::Add(258, 259),
                __Op::Mul(15, 260),
                __Op::Mul(4, 156),
                __Op::Neg(262),
                __Op::Mul(3, 151),
                __Op::Add(263, 264),
                __Op::Mul(89, 167),
                __Op::Mul(71, 265),
                __Op::Add(266, 267),
                __Op::Mul(15, 268),
            ];
            static __FLOW_OUT: [__Output; 22] = [
                __Output {
                    name: "lagrangian",
                    slot: 91,
                },
                __Output {
                    name: "dl_domega[0]",
                    slot: 94,
                },
                __Output {
                    name: "dl_domega[1]",
                    slot: 97,
                },
                __Output {
                    name: "dl_domega[2]",
                    slot: 100,
                },
                __Output {
                    name: "dl_dgamma[0]",
                    slot: 124,
                },
                __Output {
                    name: "dl_dgamma[1]",
                    slot: 147,
                },
                __Output {
                    name: "dl_dgamma[2]",
                    slot: 170,
                },
                __Output {
                    name: "d2l_domega2[0][0]",
                    slot: 173,
                },
                __Output {
                    name: "d2l_domega2[0][1]",
                    slot: 175,
                },
                __Output {
                    name: "d2l_domega2[0][2]",
                    slot: 177,
                },
                __Output {
                    name: "d2l_domega2[1][1]",
                    slot: 180,
                },
                __Output {
                    name: "d2l_domega2[1][2]",
                    slot: 182,
                },
                __Output {
                    name: "d2l_domega2[2][2]",
                    slot: 185,
                },
                __Output {
                    name: "d2l_domega_dgamma[0][0]",
                    slot: 193,
                },
                __Output {
                    name: "d2l_domega_dgamma[0][1]",
                    slot: 203,
                },
                __Output {
                    name: "d2l_domega_dgamma[0][2]",
                    slot: 213,
                },
                __Output {
                    name: "d2l_domega_dgamma[1][0]",
                    slot: 223,
                },
                __Output {
                    name: "d2l_domega_dgamma[1][1]",
                    slot: 231,
                },
                __Output {
                    name: "d2l_domega_dgamma[1][2]",
                    slot: 241,
                },
                __Output {
                    name: "d2l_domega_dgamma[2][0]",
                    slot: 251,
                },
                __Output {
                    name: "d2l_domega_dgamma[2][1]",
                    slot: 261,
                },
                __Output {
                    name: "d2l_domega_dgamma[2][2]",
                    slot: 269,
                },
            ];
            static __FLOW: __Tape = __Tape::from_static(&__FLOW_OPS, &__FLOW_OUT, 11);
            __FlowTape::new(
                    __Tape::clone(&__FLOW),
                    <[__F64]>::to_vec(
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
                    ),
                )
                .ok()
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
            let __t58 = __v7 * __v0;
            let __t59 = __v8 * __v1;
            let __t342 = __v7 * __v3;
            let __t343 = __v8 * __v4;
            let __t60 = __v9 * __v2;
            let __t344 = __v9 * __v5;
            let __t1774 = __t58 * __v3;
            let __t1771 = __t59 * __v4;
            let __t1775 = __t342 * __v0;
            let __t1772 = __t343 * __v1;
            let __t1778 = __t60 * __v5;
            let __t1779 = __t344 * __v2;
            let __t345 = __t342 * __v3;
            let __t346 = __t343 * __v4;
            let __t347 = __t344 * __v5;
            let __t1776 = __t1775 + __t1774;
            let __t1773 = __t1772 + __t1771;
            let __t1780 = __t1779 + __t1778;
            let __t348 = __t346 + __t345;
            let __t1777 = __t1773 + __t1776;
            let __t349 = __t348 + __t347;
            let __t1781 = __t1777 + __t1780;
            let __t1783 = __t1781 * (-0.5f64);
            let __t1784 = __t1783 + __v6;
            let __t1785 = __t1784 / __t349;
            __t1785
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
            let __t58 = __v7 * __v0;
            let __t59 = __v8 * __v1;
            let __t342 = __v7 * __v3;
            let __t343 = __v8 * __v4;
            let __t60 = __v9 * __v2;
            let __t22 = __t18 * __v3;
            let __t23 = __t19 * __v4;
            let __t24 = __t20 * __v5;
            let __t344 = __v9 * __v5;
            let __t1771 = __t59 * __v4;
            let __t1774 = __t58 * __v3;
            let __t1772 = __t343 * __v1;
            let __t1775 = __t342 * __v0;
            let __t25 = __t22 * __v3;
            let __t26 = __t23 * __v4;
            let __t27 = __t24 * __v5;
            let __t1778 = __t60 * __v5;
            let __t1779 = __t344 * __v2;
            let __t66 = __v4 * __v2;
            let __t1773 = __t1772 + __t1771;
            let __t1776 = __t1775 + __t1774;
            let __t67 = __v5 * __v1;
            let __t28 = __t26 + __t25;
            let __t70 = __v5 * __v0;
            let __t71 = __v3 * __v2;
            let __t1780 = __t1779 + __t1778;
            let __t74 = __v3 * __v1;
            let __t75 = __v4 * __v0;
            let __t1777 = __t1776 + __t1773;
            let __t69 = __t66 - __t67;
            let __t29 = __t28 + __t27;
            let __t345 = __t342 * __v3;
            let __t73 = __t70 - __t71;
            let __t346 = __t343 * __v4;
            let __t347 = __t344 * __v5;
            let __t77 = __t74 - __t75;
            let __t1781 = __t1777 + __t1780;
            let __t31 = __v13 * __v3;
            let __t30 = __t29.sqrt();
            let __t32 = __v14 * __v4;
            let __t61 = __t58 * __v0;
            let __t348 = __t346 + __t345;
            let __t62 = __t59 * __v1;
            let __t33 = __v15 * __v5;
            let __t1783 = __t1781 * (-0.5f64);
            let __t63 = __t60 * __v2;
            let __t87 = __v17 * __v16;
            let __t34 = __t32 + __t31;
            let __t349 = __t348 + __t347;
            let __t64 = __t62 + __t61;
            let __t1784 = __t1783 + __v6;
            let __t35 = __t34 + __t33;
            let __t65 = __t64 + __t63;
            let __t1785 = __t1784 / __t349;
            let __t43 = 1.0f64 / __t30;
            let __t37 = __t30 - __t35;
            let __t88 = __t37 * __t87;
            let __t1787 = __t1785 * __t1784;
            let __t1789 = __t1787 * (-0.5f64);
            let __t45 = __t43 * __t22;
            let __t50 = __t43 * __t23;
            let __t55 = __t43 * __t24;
            let __t47 = __t45 - __v13;
            let __t52 = __t50 - __v14;
            let __t57 = __t55 - __v15;
            let __t78 = __t47 * __t69;
            let __t79 = __t52 * __t73;
            let __t80 = __t57 * __t77;
            let __t81 = __t79 + __t78;
            let __t82 = __t81 + __t80;
            let __t83 = __t82 * __t82;
            let __t84 = __t83 * __v16;
            let __t85 = __t84 + __t65;
            let __t86 = __t85 * 0.5f64;
            let __t114 = __t86 - __t88;
            let __t1790 = __t114 + __t1789;
            __t1790
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
            let __t58 = __v7 * __v0;
            let __t59 = __v8 * __v1;
            let __t342 = __v7 * __v3;
            let __t343 = __v8 * __v4;
            let __t60 = __v9 * __v2;
            let __t22 = __t18 * __v3;
            let __t23 = __t19 * __v4;
            let __t24 = __t20 * __v5;
            let __t344 = __v9 * __v5;
            let __t1771 = __t59 * __v4;
            let __t1774 = __t58 * __v3;
            let __t1772 = __t343 * __v1;
            let __t1775 = __t342 * __v0;
            let __t25 = __t22 * __v3;
            let __t26 = __t23 * __v4;
            let __t27 = __t24 * __v5;
            let __t1778 = __t60 * __v5;
            let __t1779 = __t344 * __v2;
            let __t345 = __t342 * __v3;
            let __t1773 = __t1772 + __t1771;
            let __t1776 = __t1775 + __t1774;
            let __t346 = __t343 * __v4;
            let __t28 = __t26 + __t25;
            let __t347 = __t344 * __v5;
            let __t66 = __v4 * __v2;
            let __t1780 = __t1779 + __t1778;
            let __t67 = __v5 * __v1;
            let __t70 = __v5 * __v0;
            let __t1777 = __t1776 + __t1773;
            let __t348 = __t346 + __t345;
            let __t29 = __t28 + __t27;
            let __t71 = __v3 * __v2;
            let __t74 = __v3 * __v1;
            let __t75 = __v4 * __v0;
            let __t69 = __t66 - __t67;
            let __t1781 = __t1777 + __t1780;
            let __t349 = __t348 + __t347;
            let __t30 = __t29.sqrt();
            let __t73 = __t70 - __t71;
            let __t77 = __t74 - __t75;
            let __t1783 = __t1781 * (-0.5f64);
            let __t1784 = __t1783 + __v6;
            let __t1785 = __t1784 / __t349;
            let __t43 = 1.0f64 / __t30;
            let __t1795 = __t1785 * __t342;
            let __t1796 = __t1785 * __t343;
            let __t1797 = __t1785 * __t344;
            let __t1798 = __t1795 + __t58;
            let __t1799 = __t1796 + __t59;
            let __t1800 = __t1797 + __t60;
            let __t45 = __t43 * __t22;
            let __t50 = __t43 * __t23;
            let __t55 = __t43 * __t24;
            let __t47 = __t45 - __v13;
            let __t52 = __t50 - __v14;
            let __t57 = __t55 - __v15;
            let __t78 = __t47 * __t69;
            let __t79 = __t52 * __t73;
            let __t80 = __t57 * __t77;
            let __t98 = __t52 * __v5;
            let __t100 = __t57 * __v4;
            let __t104 = __t47 * __v5;
            let __t106 = __t57 * __v3;
            let __t109 = __t52 * __v3;
            let __t111 = __t47 * __v4;
            let __t81 = __t79 + __t78;
            let __t102 = __t98 - __t100;
            let __t107 = __t106 - __t104;
            let __t112 = __t111 - __t109;
            let __t82 = __t81 + __t80;
            let __t116 = __t82 * __t102;
            let __t122 = __t82 * __t107;
            let __t128 = __t82 * __t112;
            let __t118 = __t116 * __v16;
            let __t124 = __t122 * __v16;
            let __t130 = __t128 * __v16;
            let __t1801 = __t118 + __t1798;
            let __t1802 = __t124 + __t1799;
            let __t1803 = __t130 + __t1800;
            __Vector3::new(__t1801, __t1802, __t1803)
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
            let __t58 = __v7 * __v0;
            let __t59 = __v8 * __v1;
            let __t342 = __v7 * __v3;
            let __t343 = __v8 * __v4;
            let __t60 = __v9 * __v2;
            let __t22 = __t18 * __v3;
            let __t23 = __t19 * __v4;
            let __t24 = __t20 * __v5;
            let __t344 = __v9 * __v5;
            let __t1771 = __t59 * __v4;
            let __t1774 = __t58 * __v3;
            let __t1772 = __t343 * __v1;
            let __t1775 = __t342 * __v0;
            let __t25 = __t22 * __v3;
            let __t26 = __t23 * __v4;
            let __t27 = __t24 * __v5;
            let __t1778 = __t60 * __v5;
            let __t1779 = __t344 * __v2;
            let __t345 = __t342 * __v3;
            let __t1773 = __t1772 + __t1771;
            let __t1776 = __t1775 + __t1774;
            let __t346 = __t343 * __v4;
            let __t28 = __t26 + __t25;
            let __t66 = __v4 * __v2;
            let __t67 = __v5 * __v1;
            let __t1780 = __t1779 + __t1778;
            let __t70 = __v5 * __v0;
            let __t71 = __v3 * __v2;
            let __t1777 = __t1776 + __t1773;
            let __t347 = __t344 * __v5;
            let __t29 = __t28 + __t27;
            let __t348 = __t346 + __t345;
            let __t69 = __t66 - __t67;
            let __t74 = __v3 * __v1;
            let __t75 = __v4 * __v0;
            let __t73 = __t70 - __t71;
            let __t1781 = __t1777 + __t1780;
            let __t87 = __v17 * __v16;
            let __t30 = __t29.sqrt();
            let __t349 = __t348 + __t347;
            let __t77 = __t74 - __t75;
            let __t1783 = __t1781 * (-0.5f64);
            let __t1784 = __t1783 + __v6;
            let __t1785 = __t1784 / __t349;
            let __t43 = 1.0f64 / __t30;
            let __t1795 = __t1785 * __t342;
            let __t1796 = __t1785 * __t343;
            let __t1797 = __t1785 * __t344;
            let __t1798 = __t1795 + __t58;
            let __t1799 = __t1796 + __t59;
            let __t1800 = __t1797 + __t60;
            let __t45 = __t43 * __t22;
            let __t50 = __t43 * __t23;
            let __t55 = __t43 * __t24;
            let __t137 = __t43 * __t43;
            let __t148 = __t43 * __t18;
            let __t170 = __t43 * __t19;
            let __t217 = __t43 * __t20;
            let __t1804 = __t1798 * __t1785;
            let __t47 = __t45 - __v13;
            let __t52 = __t50 - __v14;
            let __t57 = __t55 - __v15;
            let __t138 = __t137 * __t45;
            let __t168 = __t137 * __t50;
            let __t199 = __t137 * __t55;
            let __t1806 = __t1799 * __t1785;
            let __t1808 = __t1800 * __t1785;
            let __t179 = __t47 * __v2;
            let __t144 = __t52 * __v2;
            let __t205 = __t52 * __v0;
            let __t140 = __t138 * __t23;
            let __t149 = __t138 * __t22;
            let __t171 = __t168 * __t23;
            let __t175 = __t168 * __t22;
            let __t201 = __t199 * __t23;
            let __t208 = __t199 * __t22;
            let __t154 = __t138 * __t24;
            let __t183 = __t168 * __t24;
            let __t142 = __t140 * __t73;
            let __t151 = __t148 - __t149;
            let __t173 = __t170 - __t171;
            let __t177 = __t175 * __t69;
            let __t203 = __t201 * __t73;
            let __t210 = __t208 * __t69;
            let __t212 = __t47 * __v1;
            let __t218 = __t199 * __t24;
            let __t78 = __t47 * __t69;
            let __t79 = __t52 * __t73;
            let __t146 = __t142 + __t144;
            let __t152 = __t151 * __t69;
            let __t156 = __t154 * __t77;
            let __t158 = __t57 * __v1;
            let __t174 = __t173 * __t73;
            let __t180 = __t179 - __t177;
            let __t185 = __t183 * __t77;
            let __t187 = __t57 * __v0;
            let __t206 = __t205 - __t203;
            let __t214 = __t212 + __t210;
            let __t220 = __t217 - __t218;
            let __t80 = __t57 * __t77;
            let __t81 = __t79 + __t78;
            let __t153 = __t152 - __t146;
            let __t159 = __t158 - __t156;
            let __t181 = __t180 + __t174;
            let __t189 = __t187 + __t185;
            let __t216 = __t206 - __t214;
            let __t221 = __t220 * __t77;
            let __t134 = __t47 * __t87;
            let __t82 = __t81 + __t80;
            let __t166 = __t52 * __t87;
            let __t160 = __t159 + __t153;
            let __t197 = __t57 * __t87;
            let __t191 = __t181 - __t189;
            let __t222 = __t221 + __t216;
            let __t161 = __t160 * __t82;
            let __t192 = __t191 * __t82;
            let __t223 = __t222 * __t82;
            let __t163 = __t161 * __v16;
            let __t194 = __t192 * __v16;
            let __t225 = __t223 * __v16;
            let __t165 = __t163 - __t134;
            let __t196 = __t194 - __t166;
            let __t227 = __t225 - __t197;
            let __t1805 = __t165 + __t1804;
            let __t1807 = __t196 + __t1806;
            let __t1809 = __t227 + __t1808;
            __Vector3::new(__t1805, __t1807, __t1809)
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
            let __t58 = __v7 * __v0;
            let __t59 = __v8 * __v1;
            let __t342 = __v7 * __v3;
            let __t343 = __v8 * __v4;
            let __t60 = __v9 * __v2;
            let __t344 = __v9 * __v5;
            let __t1774 = __t58 * __v3;
            let __t1771 = __t59 * __v4;
            let __t1775 = __t342 * __v0;
            let __t1772 = __t343 * __v1;
            let __t1778 = __t60 * __v5;
            let __t1779 = __t344 * __v2;
            let __t345 = __t342 * __v3;
            let __t346 = __t343 * __v4;
            let __t347 = __t344 * __v5;
            let __t1776 = __t1775 + __t1774;
            let __t1773 = __t1772 + __t1771;
            let __t1780 = __t1779 + __t1778;
            let __t348 = __t346 + __t345;
            let __t1777 = __t1773 + __t1776;
            let __t349 = __t348 + __t347;
            let __t1781 = __t1777 + __t1780;
            let __t1783 = __t1781 * (-0.5f64);
            let __t1784 = __t1783 + __v6;
            let __t1785 = __t1784 / __t349;
            let __t1897 = -__t1785;
            __t1897
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
            let __t342 = __v7 * __v3;
            let __t343 = __v8 * __v4;
            let __t344 = __v9 * __v5;
            let __t22 = __t18 * __v3;
            let __t23 = __t19 * __v4;
            let __t24 = __t20 * __v5;
            let __t345 = __t342 * __v3;
            let __t346 = __t343 * __v4;
            let __t347 = __t344 * __v5;
            let __t25 = __t22 * __v3;
            let __t26 = __t23 * __v4;
            let __t27 = __t24 * __v5;
            let __t348 = __t346 + __t345;
            let __t28 = __t26 + __t25;
            let __t349 = __t348 + __t347;
            let __t29 = __t28 + __t27;
            let __t359 = 1.0f64 / __t349;
            let __t30 = __t29.sqrt();
            let __t1816 = __t359 * __t342;
            let __t1817 = __t359 * __t343;
            let __t1818 = __t359 * __t344;
            let __t1822 = __t1816 * __t342;
            let __t1825 = __t1816 * __t343;
            let __t1828 = __t1816 * __t344;
            let __t1842 = __t1817 * __t343;
            let __t1845 = __t1817 * __t344;
            let __t43 = 1.0f64 / __t30;
            let __t1859 = __t1818 * __t344;
            let __t45 = __t43 * __t22;
            let __t50 = __t43 * __t23;
            let __t55 = __t43 * __t24;
            let __t47 = __t45 - __v13;
            let __t52 = __t50 - __v14;
            let __t57 = __t55 - __v15;
            let __t104 = __t47 * __v5;
            let __t98 = __t52 * __v5;
            let __t100 = __t57 * __v4;
            let __t106 = __t57 * __v3;
            let __t109 = __t52 * __v3;
            let __t111 = __t47 * __v4;
            let __t102 = __t98 - __t100;
            let __t107 = __t106 - __t104;
            let __t112 = __t111 - __t109;
            let __t228 = __t102 * __t102;
            let __t235 = __t107 * __t107;
            let __t231 = __t107 * __t102;
            let __t240 = __t112 * __t112;
            let __t233 = __t112 * __t102;
            let __t238 = __t112 * __t107;
            let __t229 = __t228 * __v16;
            let __t236 = __t235 * __v16;
            let __t232 = __t231 * __v16;
            let __t241 = __t240 * __v16;
            let __t234 = __t233 * __v16;
            let __t239 = __t238 * __v16;
            let __t230 = __t229 + __v7;
            let __t237 = __t236 + __v8;
            let __t1827 = __t232 - __t1825;
            let __t242 = __t241 + __v9;
            let __t1830 = __t234 - __t1828;
            let __t1847 = __t239 - __t1845;
            let __t1824 = __t230 - __t1822;
            let __t1844 = __t237 - __t1842;
            let __t1861 = __t242 - __t1859;
            __Matrix3::new(
                __t1824,
                __t1827,
                __t1830,
                __t1827,
                __t1844,
                __t1847,
                __t1830,
                __t1847,
                __t1861,
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
            let __t342 = __v7 * __v3;
            let __t343 = __v8 * __v4;
            let __t58 = __v7 * __v0;
            let __t59 = __v8 * __v1;
            let __t344 = __v9 * __v5;
            let __t22 = __t18 * __v3;
            let __t23 = __t19 * __v4;
            let __t24 = __t20 * __v5;
            let __t345 = __t342 * __v3;
            let __t346 = __t343 * __v4;
            let __t60 = __v9 * __v2;
            let __t66 = __v4 * __v2;
            let __t67 = __v5 * __v1;
            let __t25 = __t22 * __v3;
            let __t26 = __t23 * __v4;
            let __t27 = __t24 * __v5;
            let __t70 = __v5 * __v0;
            let __t71 = __v3 * __v2;
            let __t1771 = __t59 * __v4;
            let __t1772 = __t343 * __v1;
            let __t1774 = __t58 * __v3;
            let __t1775 = __t342 * __v0;
            let __t28 = __t26 + __t25;
            let __t347 = __t344 * __v5;
            let __t348 = __t346 + __t345;
            let __t69 = __t66 - __t67;
            let __t73 = __t70 - __t71;
            let __t74 = __v3 * __v1;
            let __t75 = __v4 * __v0;
            let __t1773 = __t1772 + __t1771;
            let __t29 = __t28 + __t27;
            let __t1776 = __t1775 + __t1774;
            let __t1778 = __t60 * __v5;
            let __t1779 = __t344 * __v2;
            let __t349 = __t348 + __t347;
            let __t404 = __t342 * 2f64;
            let __t77 = __t74 - __t75;
            let __t405 = __t343 * 2f64;
            let __t30 = __t29.sqrt();
            let __t1777 = __t1776 + __t1773;
            let __t406 = __t344 * 2f64;
            let __t1780 = __t1779 + __t1778;
            let __t359 = 1.0f64 / __t349;
            let __t1781 = __t1780 + __t1777;
            let __t1783 = __t1781 * (-0.5f64);
            let __t1784 = __t1783 + __v6;
            let __t1816 = __t359 * __t342;
            let __t1817 = __t359 * __t343;
            let __t1818 = __t359 * __t344;
            let __t1785 = __t1784 * __t359;
            let __t43 = 1.0f64 / __t30;
            let __t1810 = __t1785 * __t404;
            let __t1812 = __t1785 * __t405;
            let __t1814 = __t1785 * __t406;
            let __t1831 = __t1785 * __v7;
            let __t1851 = __t1785 * __v8;
            let __t1868 = __t1785 * __v9;
            let __t1811 = __t1810 + __t58;
            let __t1813 = __t1812 + __t59;
            let __t1815 = __t1814 + __t60;
            let __t1833 = __t1811 * __t1816;
            let __t1836 = __t1813 * __t1816;
            let __t1839 = __t1815 * __t1816;
            let __t1848 = __t1811 * __t1817;
            let __t1853 = __t1813 * __t1817;
            let __t45 = __t43 * __t22;
            let __t50 = __t43 * __t23;
            let __t55 = __t43 * __t24;
            let __t137 = __t43 * __t43;
            let __t148 = __t43 * __t18;
            let __t170 = __t43 * __t19;
            let __t217 = __t43 * __t20;
            let __t1856 = __t1815 * __t1817;
            let __t47 = __t45 - __v13;
            let __t52 = __t50 - __v14;
            let __t57 = __t55 - __v15;
            let __t138 = __t137 * __t45;
            let __t168 = __t137 * __t50;
            let __t199 = __t137 * __t55;
            let __t1862 = __t1811 * __t1818;
            let __t1865 = __t1813 * __t1818;
            let __t179 = __t47 * __v2;
            let __t144 = __t52 * __v2;
            let __t205 = __t52 * __v0;
            let __t140 = __t138 * __t23;
            let __t149 = __t138 * __t22;
            let __t171 = __t168 * __t23;
            let __t175 = __t168 * __t22;
            let __t201 = __t199 * __t23;
            let __t208 = __t199 * __t22;
            let __t154 = __t138 * __t24;
            let __t183 = __t168 * __t24;
            let __t142 = __t140 * __t73;
            let __t151 = __t148 - __t149;
            let __t173 = __t170 - __t171;
            let __t177 = __t175 * __t69;
            let __t203 = __t201 * __t73;
            let __t210 = __t208 * __t69;
            let __t212 = __t47 * __v1;
            let __t218 = __t199 * __t24;
            let __t78 = __t47 * __t69;
            let __t79 = __t52 * __t73;
            let __t146 = __t142 + __t144;
            let __t152 = __t151 * __t69;
            let __t156 = __t154 * __t77;
            let __t158 = __t57 * __v1;
            let __t174 = __t173 * __t73;
            let __t180 = __t179 - __t177;
            let __t185 = __t183 * __t77;
            let __t187 = __t57 * __v0;
            let __t206 = __t205 - __t203;
            let __t214 = __t212 + __t210;
            let __t220 = __t217 - __t218;
            let __t80 = __t57 * __t77;
            let __t81 = __t79 + __t78;
            let __t98 = __t52 * __v5;
            let __t100 = __t57 * __v4;
            let __t104 = __t47 * __v5;
            let __t106 = __t57 * __v3;
            let __t109 = __t52 * __v3;
            let __t111 = __t47 * __v4;
            let __t153 = __t152 - __t146;
            let __t159 = __t158 - __t156;
            let __t181 = __t180 + __t174;
            let __t189 = __t187 + __t185;
            let __t216 = __t206 - __t214;
            let __t221 = __t220 * __t77;
            let __t243 = __t154 * __v4;
            let __t245 = __t140 * __v5;
            let __t252 = __t183 * __v4;
            let __t264 = __t201 * __v5;
            let __t272 = __t154 * __v3;
            let __t282 = __t183 * __v3;
            let __t284 = __t175 * __v5;
            let __t292 = __t208 * __v5;
            let __t302 = __t140 * __v3;
            let __t311 = __t175 * __v4;
            let __t321 = __t208 * __v4;
            let __t323 = __t201 * __v3;
            let __t82 = __t81 + __t80;
            let __t102 = __t98 - __t100;
            let __t107 = __t106 - __t104;
            let __t112 = __t111 - __t109;
            let __t160 = __t159 + __t153;
            let __t191 = __t181 - __t189;
            let __t222 = __t221 + __t216;
            let __t247 = __t243 - __t245;
            let __t254 = __t57 - __t252;
            let __t256 = __t173 * __v5;
            let __t262 = __t220 * __v4;
            let __t266 = __t52 - __t264;
            let __t274 = __t57 - __t272;
            let __t275 = __t151 * __v5;
            let __t286 = __t284 - __t282;
            let __t291 = __t220 * __v3;
            let __t294 = __t47 - __t292;
            let __t301 = __t151 * __v4;
            let __t304 = __t52 - __t302;
            let __t313 = __t47 - __t311;
            let __t314 = __t173 * __v3;
            let __t325 = __t323 - __t321;
            let __t248 = __t160 * __t102;
            let __t249 = __t247 * __t82;
            let __t257 = __t256 - __t254;
            let __t267 = __t266 - __t262;
            let __t277 = __t274 - __t275;
            let __t287 = __t191 * __t107;
            let __t288 = __t286 * __t82;
            let __t296 = __t291 - __t294;
            let __t306 = __t301 - __t304;
            let __t316 = __t313 - __t314;
            let __t326 = __t222 * __t112;
            let __t327 = __t325 * __t82;
            let __t250 = __t249 + __t248;
            let __t258 = __t191 * __t102;
            let __t259 = __t257 * __t82;
            let __t268 = __t222 * __t102;
            let __t269 = __t267 * __t82;
            let __t278 = __t160 * __t107;
            let __t279 = __t277 * __t82;
            let __t289 = __t288 + __t287;
            let __t297 = __t222 * __t107;
            let __t298 = __t296 * __t82;
            let __t307 = __t160 * __t112;
            let __t308 = __t306 * __t82;
            let __t317 = __t191 * __t112;
            let __t318 = __t316 * __t82;
            let __t328 = __t327 + __t326;
            let __t251 = __t250 * __v16;
            let __t260 = __t259 + __t258;
            let __t270 = __t269 + __t268;
            let __t280 = __t279 + __t278;
            let __t290 = __t289 * __v16;
            let __t299 = __t298 + __t297;
            let __t309 = __t308 + __t307;
            let __t319 = __t318 + __t317;
            let __t329 = __t328 * __v16;
            let __t261 = __t260 * __v16;
            let __t271 = __t270 * __v16;
            let __t281 = __t280 * __v16;
            let __t1832 = __t251 + __t1831;
            let __t300 = __t299 * __v16;
            let __t310 = __t309 * __v16;
            let __t320 = __t319 * __v16;
            let __t1852 = __t290 + __t1851;
            let __t1869 = __t329 + __t1868;
            let __t1870 = __t1815 * __t1818;
            let __t1838 = __t261 - __t1836;
            let __t1835 = __t1832 - __t1833;
            let __t1841 = __t271 - __t1839;
            let __t1850 = __t281 - __t1848;
            let __t1858 = __t300 - __t1856;
            let __t1855 = __t1852 - __t1853;
            let __t1864 = __t310 - __t1862;
            let __t1867 = __t320 - __t1865;
            let __t1872 = __t1869 - __t1870;
            __Matrix3::new(
                __t1835,
                __t1838,
                __t1841,
                __t1850,
                __t1855,
                __t1858,
                __t1864,
                __t1867,
                __t1872,
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
            let __t342 = __v7 * __v3;
            let __t343 = __v8 * __v4;
            let __t58 = __v7 * __v0;
            let __t59 = __v8 * __v1;
            let __t344 = __v9 * __v5;
            let __t22 = __t18 * __v3;
            let __t23 = __t19 * __v4;
            let __t24 = __t20 * __v5;
            let __t345 = __t342 * __v3;
            let __t346 = __t343 * __v4;
            let __t60 = __v9 * __v2;
            let __t66 = __v4 * __v2;
            let __t67 = __v5 * __v1;
            let __t25 = __t22 * __v3;
            let __t26 = __t23 * __v4;
            let __t27 = __t24 * __v5;
            let __t70 = __v5 * __v0;
            let __t71 = __v3 * __v2;
            let __t1771 = __t59 * __v4;
            let __t1772 = __t343 * __v1;
            let __t1774 = __t58 * __v3;
            let __t1775 = __t342 * __v0;
            let __t28 = __t26 + __t25;
            let __t347 = __t344 * __v5;
            let __t348 = __t346 + __t345;
            let __t69 = __t66 - __t67;
            let __t73 = __t70 - __t71;
            let __t74 = __v3 * __v1;
            let __t75 = __v4 * __v0;
            let __t1773 = __t1772 + __t1771;
            let __t29 = __t28 + __t27;
            let __t1776 = __t1775 + __t1774;
            let __t1778 = __t60 * __v5;
            let __t1779 = __t344 * __v2;
            let __t349 = __t348 + __t347;
            let __t404 = __t342 * 2f64;
            let __t77 = __t74 - __t75;
            let __t405 = __t343 * 2f64;
            let __t30 = __t29.sqrt();
            let __t1777 = __t1776 + __t1773;
            let __t406 = __t344 * 2f64;
            let __t1780 = __t1779 + __t1778;
            let __t359 = 1.0f64 / __t349;
            let __t87 = __v17 * __v16;
            let __t1781 = __t1780 + __t1777;
            let __t1783 = __t1781 * (-0.5f64);
            let __t1784 = __t1783 + __v6;
            let __t1785 = __t1784 * __t359;
            let __t43 = 1.0f64 / __t30;
            let __t1810 = __t1785 * __t404;
            let __t1812 = __t1785 * __t405;
            let __t1814 = __t1785 * __t406;
            let __t1831 = __t1785 * __v7;
            let __t1851 = __t1785 * __v8;
            let __t1868 = __t1785 * __v9;
            let __t1811 = __t1810 + __t58;
            let __t1813 = __t1812 + __t59;
            let __t1815 = __t1814 + __t60;
            let __t1873 = __t1831 * __t1785;
            let __t1884 = __t1851 * __t1785;
            let __t1892 = __t1868 * __t1785;
            let __t1819 = __t1811 * __t359;
            let __t1820 = __t1813 * __t359;
            let __t1821 = __t1815 * __t359;
            let __t45 = __t43 * __t22;
            let __t50 = __t43 * __t23;
            let __t55 = __t43 * __t24;
            let __t137 = __t43 * __t43;
            let __t148 = __t43 * __t18;
            let __t170 = __t43 * __t19;
            let __t217 = __t43 * __t20;
            let __t1875 = __t1819 * __t1811;
            let __t47 = __t45 - __v13;
            let __t52 = __t50 - __v14;
            let __t57 = __t55 - __v15;
            let __t138 = __t137 * __t45;
            let __t168 = __t137 * __t50;
            let __t199 = __t137 * __t55;
            let __t1878 = __t1819 * __t1813;
            let __t1881 = __t1819 * __t1815;
            let __t179 = __t47 * __v2;
            let __t144 = __t52 * __v2;
            let __t205 = __t52 * __v0;
            let __t149 = __t138 * __t22;
            let __t171 = __t168 * __t23;
            let __t218 = __t199 * __t24;
            let __t641 = __t138 * __t43;
            let __t748 = __t168 * __t43;
            let __t847 = __t199 * __t43;
            let __t175 = __t168 * __t22;
            let __t201 = __t199 * __t23;
            let __t151 = __t148 - __t149;
            let __t173 = __t170 - __t171;
            let __t208 = __t199 * __t22;
            let __t220 = __t217 - __t218;
            let __t646 = __t641 * __t45;
            let __t753 = __t748 * __t45;
            let __t852 = __t847 * __t45;
            let __t950 = __t748 * __t50;
            let __t1053 = __t847 * __t50;
            let __t1148 = __t847 * __t55;
            let __t645 = __t151 * __t137;
            let __t751 = __t175 * __t137;
            let __t647 = __t646 * (-2f64);
            let __t754 = __t753 * (-2f64);
            let __t850 = __t208 * __t137;
            let __t853 = __t852 * (-2f64);
            let __t949 = __t173 * __t137;
            let __t951 = __t950 * (-2f64);
            let __t1051 = __t201 * __t137;
            let __t1054 = __t1053 * (-2f64);
            let __t1147 = __t220 * __t137;
            let __t1149 = __t1148 * (-2f64);
            let __t140 = __t138 * __t23;
            let __t648 = __t647 + __t645;
            let __t656 = __t138 * __t18;
            let __t755 = __t754 - __t751;
            let __t854 = __t853 - __t850;
            let __t952 = __t951 + __t949;
            let __t968 = __t168 * __t19;
            let __t1055 = __t1054 - __t1051;
            let __t1150 = __t1149 + __t1147;
            let __t154 = __t138 * __t24;
            let __t183 = __t168 * __t24;
            let __t657 = __t648 * __t22;
            let __t661 = __t656 * 2f64;
            let __t666 = __t140 * __v2;
            let __t668 = __t648 * __t23;
            let __t764 = __t755 * __t22;
            let __t766 = __t168 * __t18;
            let __t775 = __t138 * __t19;
            let __t776 = __t755 * __t23;
            let __t861 = __t854 * __t22;
            let __t863 = __t199 * __t18;
            let __t875 = __t854 * __t23;
            let __t959 = __t175 * __v2;
            let __t961 = __t952 * __t22;
            let __t969 = __t952 * __t23;
            let __t973 = __t968 * 2f64;
            let __t1064 = __t1055 * __t22;
            let __t1072 = __t1055 * __t23;
            let __t1074 = __t199 * __t19;
            let __t1151 = __t199 * __t20;
            let __t1161 = __t208 * __v1;
            let __t1163 = __t1150 * __t22;
            let __t1169 = __t201 * __v0;
            let __t1171 = __t1150 * __t23;
            let __t142 = __t140 * __t73;
            let __t177 = __t175 * __t69;
            let __t203 = __t201 * __t73;
            let __t210 = __t208 * __t69;
            let __t212 = __t47 * __v1;
            let __t638 = __t154 * __v1;
            let __t649 = __t648 * __t24;
            let __t662 = __t661 + __t657;
            let __t669 = __t668 * __t73;
            let __t671 = __t666 * (-2f64);
            let __t756 = __t755 * __t24;
            let __t768 = __t766 + __t764;
            let __t777 = __t776 + __t775;
            let __t855 = __t138 * __t20;
            let __t856 = __t854 * __t24;
            let __t865 = __t863 + __t861;
            let __t876 = __t140 * __v0;
            let __t877 = __t875 * __t73;
            let __t947 = __t183 * __v0;
            let __t953 = __t952 * __t24;
            let __t962 = __t961 * __t69;
            let __t965 = __t959 * 2f64;
            let __t974 = __t973 + __t969;
            let __t1056 = __t168 * __t20;
            let __t1057 = __t1055 * __t24;
            let __t1065 = __t175 * __v1;
            let __t1067 = __t1064 * __t69;
            let __t1076 = __t1074 + __t1072;
            let __t1152 = __t1150 * __t24;
            let __t1156 = __t1151 * 2f64;
            let __t1164 = __t1163 * __t69;
            let __t1166 = __t1161 * (-2f64);
            let __t1172 = __t1171 * __t73;
            let __t1175 = __t1169 * 2f64;
            let __t78 = __t47 * __t69;
            let __t79 = __t52 * __t73;
            let __t146 = __t142 + __t144;
            let __t152 = __t151 * __t69;
            let __t156 = __t154 * __t77;
            let __t158 = __t57 * __v1;
            let __t174 = __t173 * __t73;
            let __t180 = __t179 - __t177;
            let __t185 = __t183 * __t77;
            let __t187 = __t57 * __v0;
            let __t206 = __t205 - __t203;
            let __t214 = __t212 + __t210;
            let __t650 = __t649 * __t77;
            let __t653 = __t638 * 2f64;
            let __t664 = __t662 * __t69;
            let __t672 = __t671 + __t669;
            let __t757 = __t154 * __v0;
            let __t759 = __t756 * __t77;
            let __t770 = __t151 * __v2;
            let __t771 = __t768 * __t69;
            let __t774 = __t173 * __v2;
            let __t778 = __t777 * __t73;
            let __t857 = __t856 + __t855;
            let __t867 = __t151 * __v1;
            let __t869 = __t865 * __t69;
            let __t873 = __t201 * __v2;
            let __t878 = __t877 + __t876;
            let __t954 = __t953 * __t77;
            let __t956 = __t947 * (-2f64);
            let __t966 = __t965 + __t962;
            let __t976 = __t974 * __t73;
            let __t1058 = __t1057 + __t1056;
            let __t1062 = __t208 * __v2;
            let __t1068 = __t1067 - __t1065;
            let __t1078 = __t173 * __v0;
            let __t1079 = __t1076 * __t73;
            let __t1157 = __t1156 + __t1152;
            let __t1167 = __t1166 + __t1164;
            let __t1176 = __t1175 + __t1172;
            let __t80 = __t57 * __t77;
            let __t81 = __t79 + __t78;
            let __t153 = __t152 - __t146;
            let __t159 = __t158 - __t156;
            let __t181 = __t180 + __t174;
            let __t189 = __t187 + __t185;
            let __t216 = __t206 - __t214;
            let __t221 = __t220 * __t77;
            let __t654 = __t653 + __t650;
            let __t674 = __t672 + __t664;
            let __t746 = __t183 * __v1;
            let __t760 = __t759 - __t757;
            let __t773 = __t770 - __t771;
            let __t779 = __t778 + __t774;
            let __t846 = __t220 * __v1;
            let __t858 = __t857 * __t77;
            let __t871 = __t869 + __t867;
            let __t879 = __t878 - __t873;
            let __t957 = __t956 + __t954;
            let __t978 = __t976 + __t966;
            let __t1050 = __t220 * __v0;
            let __t1059 = __t1058 * __t77;
            let __t1070 = __t1068 + __t1062;
            let __t1081 = __t1078 - __t1079;
            let __t1159 = __t1157 * __t77;
            let __t1178 = __t1176 + __t1167;
            let __t82 = __t81 + __t80;
            let __t160 = __t159 + __t153;
            let __t191 = __t181 - __t189;
            let __t222 = __t221 + __t216;
            let __t676 = __t674 + __t654;
            let __t762 = __t760 + __t746;
            let __t781 = __t773 - __t779;
            let __t860 = __t846 - __t858;
            let __t881 = __t879 + __t871;
            let __t980 = __t978 + __t957;
            let __t1060 = __t1059 + __t1050;
            let __t1082 = __t1081 - __t1070;
            let __t1180 = __t1178 + __t1159;
            let __t678 = __t160 * __t160;
            let __t679 = __t676 * __t82;
            let __t782 = __t781 - __t762;
            let __t883 = __t860 - __t881;
            let __t982 = __t191 * __t191;
            let __t983 = __t980 * __t82;
            let __t1083 = __t1082 - __t1060;
            let __t1182 = __t222 * __t222;
            let __t1183 = __t1180 * __t82;
            let __t681 = __t678 - __t679;
            let __t783 = __t191 * __t160;
            let __t784 = __t782 * __t82;
            let __t884 = __t222 * __t160;
            let __t885 = __t883 * __t82;
            let __t985 = __t982 - __t983;
            let __t1084 = __t222 * __t191;
            let __t1085 = __t1083 * __t82;
            let __t1185 = __t1182 - __t1183;
            let __t682 = __t681 * __v16;
            let __t683 = __t151 * __t87;
            let __t785 = __t784 + __t783;
            let __t886 = __t885 + __t884;
            let __t986 = __t985 * __v16;
            let __t987 = __t173 * __t87;
            let __t1086 = __t1085 + __t1084;
            let __t1186 = __t1185 * __v16;
            let __t1187 = __t220 * __t87;
            let __t685 = __t682 - __t683;
            let __t786 = __t785 * __v16;
            let __t787 = __t175 * __t87;
            let __t887 = __t886 * __v16;
            let __t888 = __t208 * __t87;
            let __t989 = __t986 - __t987;
            let __t1087 = __t1086 * __v16;
            let __t1088 = __t201 * __t87;
            let __t1189 = __t1186 - __t1187;
            let __t1874 = __t685 + __t1873;
            let __t789 = __t787 + __t786;
            let __t1886 = __t1820 * __t1813;
            let __t890 = __t888 + __t887;
            let __t1885 = __t989 + __t1884;
            let __t1889 = __t1820 * __t1815;
            let __t1090 = __t1088 + __t1087;
            let __t1893 = __t1189 + __t1892;
            let __t1894 = __t1821 * __t1815;
            let __t1877 = __t1874 - __t1875;
            let __t1880 = __t789 - __t1878;
            let __t1883 = __t890 - __t1881;
            let __t1888 = __t1885 - __t1886;
            let __t1891 = __t1090 - __t1889;
            let __t1896 = __t1893 - __t1894;
            __Matrix3::new(
                __t1877,
                __t1880,
                __t1883,
                __t1880,
                __t1888,
                __t1891,
                __t1883,
                __t1891,
                __t1896,
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
            let __t342 = __v7 * __v3;
            let __t343 = __v8 * __v4;
            let __t344 = __v9 * __v5;
            let __t31 = __v13 * __v3;
            let __t32 = __v14 * __v4;
            let __t22 = __t18 * __v3;
            let __t23 = __t19 * __v4;
            let __t24 = __t20 * __v5;
            let __t345 = __t342 * __v3;
            let __t346 = __t343 * __v4;
            let __t347 = __t344 * __v5;
            let __t33 = __v15 * __v5;
            let __t34 = __t32 + __t31;
            let __t25 = __t22 * __v3;
            let __t26 = __t23 * __v4;
            let __t27 = __t24 * __v5;
            let __t87 = __v17 * __v16;
            let __t348 = __t346 + __t345;
            let __t35 = __t34 + __t33;
            let __t28 = __t26 + __t25;
            let __t349 = __t348 + __t347;
            let __t29 = __t28 + __t27;
            let __t1251 = __v6 / __t349;
            let __t30 = __t29.sqrt();
            let __t1253 = __t1251 * __v6;
            let __t1255 = __t1253 * (-0.5f64);
            let __t37 = __t30 - __t35;
            let __t88 = __t37 * __t87;
            let __t1256 = __t1255 - __t88;
            let __t1401 = -__t1256;
            __t1401
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
            let __t342 = __v7 * __v3;
            let __t343 = __v8 * __v4;
            let __t58 = __v7 * __v0;
            let __t59 = __v8 * __v1;
            let __t344 = __v9 * __v5;
            let __t22 = __t18 * __v3;
            let __t23 = __t19 * __v4;
            let __t24 = __t20 * __v5;
            let __t345 = __t342 * __v3;
            let __t346 = __t343 * __v4;
            let __t60 = __v9 * __v2;
            let __t66 = __v4 * __v2;
            let __t67 = __v5 * __v1;
            let __t25 = __t22 * __v3;
            let __t26 = __t23 * __v4;
            let __t27 = __t24 * __v5;
            let __t70 = __v5 * __v0;
            let __t71 = __v3 * __v2;
            let __t1771 = __t59 * __v4;
            let __t1772 = __t343 * __v1;
            let __t1774 = __t58 * __v3;
            let __t1775 = __t342 * __v0;
            let __t28 = __t26 + __t25;
            let __t347 = __t344 * __v5;
            let __t348 = __t346 + __t345;
            let __t69 = __t66 - __t67;
            let __t73 = __t70 - __t71;
            let __t74 = __v3 * __v1;
            let __t75 = __v4 * __v0;
            let __t1773 = __t1772 + __t1771;
            let __t29 = __t28 + __t27;
            let __t1776 = __t1775 + __t1774;
            let __t1778 = __t60 * __v5;
            let __t1779 = __t344 * __v2;
            let __t349 = __t348 + __t347;
            let __t31 = __v13 * __v3;
            let __t77 = __t74 - __t75;
            let __t32 = __v14 * __v4;
            let __t30 = __t29.sqrt();
            let __t1777 = __t1776 + __t1773;
            let __t61 = __t58 * __v0;
            let __t1780 = __t1779 + __t1778;
            let __t359 = 1.0f64 / __t349;
            let __t62 = __t59 * __v1;
            let __t33 = __v15 * __v5;
            let __t34 = __t32 + __t31;
            let __t63 = __t60 * __v2;
            let __t404 = __t342 * 2f64;
            let __t405 = __t343 * 2f64;
            let __t1781 = __t1780 + __t1777;
            let __t406 = __t344 * 2f64;
            let __t64 = __t62 + __t61;
            let __t87 = __v17 * __v16;
            let __t35 = __t34 + __t33;
            let __t1783 = __t1781 * (-0.5f64);
            let __t65 = __t64 + __t63;
            let __t1784 = __t1783 + __v6;
            let __t1816 = __t359 * __t342;
            let __t1817 = __t359 * __t343;
            let __t1818 = __t359 * __t344;
            let __t1785 = __t1784 * __t359;
            let __t43 = 1.0f64 / __t30;
            let __t37 = __t30 - __t35;
            let __t1822 = __t1816 * __t342;
            let __t1825 = __t1816 * __t343;
            let __t1828 = __t1816 * __t344;
            let __t1810 = __t1785 * __t404;
            let __t1812 = __t1785 * __t405;
            let __t1814 = __t1785 * __t406;
            let __t1795 = __t1785 * __t342;
            let __t1796 = __t1785 * __t343;
            let __t1797 = __t1785 * __t344;
            let __t1831 = __t1785 * __v7;
            let __t1851 = __t1785 * __v8;
            let __t1811 = __t1810 + __t58;
            let __t1813 = __t1812 + __t59;
            let __t1815 = __t1814 + __t60;
            let __t1868 = __t1785 * __v9;
            let __t88 = __t37 * __t87;
            let __t1787 = __t1785 * __t1784;
            let __t1798 = __t1795 + __t58;
            let __t1799 = __t1796 + __t59;
            let __t1800 = __t1797 + __t60;
            let __t1819 = __t1811 * __t359;
            let __t1820 = __t1813 * __t359;
            let __t1821 = __t1815 * __t359;
            let __t1873 = __t1831 * __t1785;
            let __t45 = __t43 * __t22;
            let __t50 = __t43 * __t23;
            let __t55 = __t43 * __t24;
            let __t137 = __t43 * __t43;
            let __t148 = __t43 * __t18;
            let __t170 = __t43 * __t19;
            let __t217 = __t43 * __t20;
            let __t1884 = __t1851 * __t1785;
            let __t47 = __t45 - __v13;
            let __t52 = __t50 - __v14;
            let __t57 = __t55 - __v15;
            let __t138 = __t137 * __t45;
            let __t168 = __t137 * __t50;
            let __t199 = __t137 * __t55;
            let __t1892 = __t1868 * __t1785;
            let __t1789 = __t1787 * (-0.5f64);
            let __t179 = __t47 * __v2;
            let __t144 = __t52 * __v2;
            let __t205 = __t52 * __v0;
            let __t149 = __t138 * __t22;
            let __t171 = __t168 * __t23;
            let __t218 = __t199 * __t24;
            let __t641 = __t138 * __t43;
            let __t748 = __t168 * __t43;
            let __t847 = __t199 * __t43;
            let __t175 = __t168 * __t22;
            let __t201 = __t199 * __t23;
            let __t151 = __t148 - __t149;
            let __t173 = __t170 - __t171;
            let __t208 = __t199 * __t22;
            let __t220 = __t217 - __t218;
            let __t646 = __t641 * __t45;
            let __t753 = __t748 * __t45;
            let __t852 = __t847 * __t45;
            let __t950 = __t748 * __t50;
            let __t1053 = __t847 * __t50;
            let __t1148 = __t847 * __t55;
            let __t645 = __t151 * __t137;
            let __t751 = __t175 * __t137;
            let __t647 = __t646 * (-2f64);
            let __t754 = __t753 * (-2f64);
            let __t850 = __t208 * __t137;
            let __t853 = __t852 * (-2f64);
            let __t949 = __t173 * __t137;
            let __t951 = __t950 * (-2f64);
            let __t1051 = __t201 * __t137;
            let __t1054 = __t1053 * (-2f64);
            let __t1147 = __t220 * __t137;
            let __t1149 = __t1148 * (-2f64);
            let __t140 = __t138 * __t23;
            let __t648 = __t647 + __t645;
            let __t656 = __t138 * __t18;
            let __t755 = __t754 - __t751;
            let __t854 = __t853 - __t850;
            let __t952 = __t951 + __t949;
            let __t968 = __t168 * __t19;
            let __t1055 = __t1054 - __t1051;
            let __t1150 = __t1149 + __t1147;
            let __t154 = __t138 * __t24;
            let __t183 = __t168 * __t24;
            let __t657 = __t648 * __t22;
            let __t661 = __t656 * 2f64;
            let __t666 = __t140 * __v2;
            let __t668 = __t648 * __t23;
            let __t764 = __t755 * __t22;
            let __t766 = __t168 * __t18;
            let __t775 = __t138 * __t19;
            let __t776 = __t755 * __t23;
            let __t861 = __t854 * __t22;
            let __t863 = __t199 * __t18;
            let __t875 = __t854 * __t23;
            let __t959 = __t175 * __v2;
            let __t961 = __t952 * __t22;
            let __t969 = __t952 * __t23;
            let __t973 = __t968 * 2f64;
            let __t1064 = __t1055 * __t22;
            let __t1072 = __t1055 * __t23;
            let __t1074 = __t199 * __t19;
            let __t1151 = __t199 * __t20;
            let __t1161 = __t208 * __v1;
            let __t1163 = __t1150 * __t22;
            let __t1169 = __t201 * __v0;
            let __t1171 = __t1150 * __t23;
            let __t142 = __t140 * __t73;
            let __t177 = __t175 * __t69;
            let __t203 = __t201 * __t73;
            let __t210 = __t208 * __t69;
            let __t212 = __t47 * __v1;
            let __t638 = __t154 * __v1;
            let __t649 = __t648 * __t24;
            let __t662 = __t661 + __t657;
            let __t669 = __t668 * __t73;
            let __t671 = __t666 * (-2f64);
            let __t756 = __t755 * __t24;
            let __t768 = __t766 + __t764;
            let __t777 = __t776 + __t775;
            let __t855 = __t138 * __t20;
            let __t856 = __t854 * __t24;
            let __t865 = __t863 + __t861;
            let __t876 = __t140 * __v0;
            let __t877 = __t875 * __t73;
            let __t947 = __t183 * __v0;
            let __t953 = __t952 * __t24;
            let __t962 = __t961 * __t69;
            let __t965 = __t959 * 2f64;
            let __t974 = __t973 + __t969;
            let __t1056 = __t168 * __t20;
            let __t1057 = __t1055 * __t24;
            let __t1065 = __t175 * __v1;
            let __t1067 = __t1064 * __t69;
            let __t1076 = __t1074 + __t1072;
            let __t1152 = __t1150 * __t24;
            let __t1156 = __t1151 * 2f64;
            let __t1164 = __t1163 * __t69;
            let __t1166 = __t1161 * (-2f64);
            let __t1172 = __t1171 * __t73;
            let __t1175 = __t1169 * 2f64;
            let __t78 = __t47 * __t69;
            let __t79 = __t52 * __t73;
            let __t146 = __t142 + __t144;
            let __t152 = __t151 * __t69;
            let __t156 = __t154 * __t77;
            let __t158 = __t57 * __v1;
            let __t174 = __t173 * __t73;
            let __t180 = __t179 - __t177;
            let __t185 = __t183 * __t77;
            let __t187 = __t57 * __v0;
            let __t206 = __t205 - __t203;
            let __t214 = __t212 + __t210;
            let __t650 = __t649 * __t77;
            let __t653 = __t638 * 2f64;
            let __t664 = __t662 * __t69;
            let __t672 = __t671 + __t669;
            let __t757 = __t154 * __v0;
            let __t759 = __t756 * __t77;
            let __t770 = __t151 * __v2;
            let __t771 = __t768 * __t69;
            let __t774 = __t173 * __v2;
            let __t778 = __t777 * __t73;
            let __t857 = __t856 + __t855;
            let __t867 = __t151 * __v1;
            let __t869 = __t865 * __t69;
            let __t873 = __t201 * __v2;
            let __t878 = __t877 + __t876;
            let __t954 = __t953 * __t77;
            let __t956 = __t947 * (-2f64);
            let __t966 = __t965 + __t962;
            let __t976 = __t974 * __t73;
            let __t1058 = __t1057 + __t1056;
            let __t1062 = __t208 * __v2;
            let __t1068 = __t1067 - __t1065;
            let __t1078 = __t173 * __v0;
            let __t1079 = __t1076 * __t73;
            let __t1157 = __t1156 + __t1152;
            let __t1167 = __t1166 + __t1164;
            let __t1176 = __t1175 + __t1172;
            let __t80 = __t57 * __t77;
            let __t81 = __t79 + __t78;
            let __t153 = __t152 - __t146;
            let __t159 = __t158 - __t156;
            let __t181 = __t180 + __t174;
            let __t189 = __t187 + __t185;
            let __t216 = __t206 - __t214;
            let __t221 = __t220 * __t77;
            let __t654 = __t653 + __t650;
            let __t674 = __t672 + __t664;
            let __t746 = __t183 * __v1;
            let __t760 = __t759 - __t757;
            let __t773 = __t770 - __t771;
            let __t779 = __t778 + __t774;
            let __t846 = __t220 * __v1;
            let __t858 = __t857 * __t77;
            let __t871 = __t869 + __t867;
            let __t879 = __t878 - __t873;
            let __t957 = __t956 + __t954;
            let __t978 = __t976 + __t966;
            let __t1050 = __t220 * __v0;
            let __t1059 = __t1058 * __t77;
            let __t1070 = __t1068 + __t1062;
            let __t1081 = __t1078 - __t1079;
            let __t1159 = __t1157 * __t77;
            let __t1178 = __t1176 + __t1167;
            let __t82 = __t81 + __t80;
            let __t98 = __t52 * __v5;
            let __t100 = __t57 * __v4;
            let __t104 = __t47 * __v5;
            let __t106 = __t57 * __v3;
            let __t109 = __t52 * __v3;
            let __t111 = __t47 * __v4;
            let __t160 = __t159 + __t153;
            let __t191 = __t181 - __t189;
            let __t222 = __t221 + __t216;
            let __t243 = __t154 * __v4;
            let __t245 = __t140 * __v5;
            let __t252 = __t183 * __v4;
            let __t264 = __t201 * __v5;
            let __t272 = __t154 * __v3;
            let __t282 = __t183 * __v3;
            let __t284 = __t175 * __v5;
            let __t292 = __t208 * __v5;
            let __t302 = __t140 * __v3;
            let __t311 = __t175 * __v4;
            let __t321 = __t208 * __v4;
            let __t323 = __t201 * __v3;
            let __t676 = __t674 + __t654;
            let __t762 = __t760 + __t746;
            let __t781 = __t773 - __t779;
            let __t860 = __t846 - __t858;
            let __t881 = __t879 + __t871;
            let __t980 = __t978 + __t957;
            let __t1060 = __t1059 + __t1050;
            let __t1082 = __t1081 - __t1070;
            let __t1180 = __t1178 + __t1159;
            let __t83 = __t82 * __t82;
            let __t102 = __t98 - __t100;
            let __t107 = __t106 - __t104;
            let __t112 = __t111 - __t109;
            let __t247 = __t243 - __t245;
            let __t254 = __t57 - __t252;
            let __t256 = __t173 * __v5;
            let __t262 = __t220 * __v4;
            let __t266 = __t52 - __t264;
            let __t274 = __t57 - __t272;
            let __t275 = __t151 * __v5;
            let __t286 = __t284 - __t282;
            let __t291 = __t220 * __v3;
            let __t294 = __t47 - __t292;
            let __t301 = __t151 * __v4;
            let __t304 = __t52 - __t302;
            let __t313 = __t47 - __t311;
            let __t314 = __t173 * __v3;
            let __t325 = __t323 - __t321;
            let __t678 = __t160 * __t160;
            let __t679 = __t676 * __t82;
            let __t782 = __t781 - __t762;
            let __t883 = __t860 - __t881;
            let __t982 = __t191 * __t191;
            let __t983 = __t980 * __t82;
            let __t1083 = __t1082 - __t1060;
            let __t1182 = __t222 * __t222;
            let __t1183 = __t1180 * __t82;
            let __t84 = __t83 * __v16;
            let __t248 = __t102 * __t160;
            let __t249 = __t247 * __t82;
            let __t257 = __t256 - __t254;
            let __t267 = __t266 - __t262;
            let __t277 = __t274 - __t275;
            let __t287 = __t107 * __t191;
            let __t288 = __t286 * __t82;
            let __t296 = __t291 - __t294;
            let __t306 = __t301 - __t304;
            let __t316 = __t313 - __t314;
            let __t326 = __t112 * __t222;
            let __t327 = __t325 * __t82;
            let __t681 = __t678 - __t679;
            let __t783 = __t191 * __t160;
            let __t784 = __t782 * __t82;
            let __t884 = __t222 * __t160;
            let __t885 = __t883 * __t82;
            let __t985 = __t982 - __t983;
            let __t1084 = __t222 * __t191;
            let __t1085 = __t1083 * __t82;
            let __t1185 = __t1182 - __t1183;
            let __t85 = __t84 + __t65;
            let __t161 = __t160 * __t82;
            let __t192 = __t191 * __t82;
            let __t223 = __t222 * __t82;
            let __t228 = __t102 * __t102;
            let __t235 = __t107 * __t107;
            let __t240 = __t112 * __t112;
            let __t250 = __t249 + __t248;
            let __t258 = __t102 * __t191;
            let __t259 = __t257 * __t82;
            let __t268 = __t102 * __t222;
            let __t269 = __t267 * __t82;
            let __t278 = __t107 * __t160;
            let __t279 = __t277 * __t82;
            let __t289 = __t288 + __t287;
            let __t297 = __t107 * __t222;
            let __t298 = __t296 * __t82;
            let __t307 = __t112 * __t160;
            let __t308 = __t306 * __t82;
            let __t317 = __t112 * __t191;
            let __t318 = __t316 * __t82;
            let __t328 = __t327 + __t326;
            let __t682 = __t681 * __v16;
            let __t683 = __t151 * __t87;
            let __t785 = __t784 + __t783;
            let __t886 = __t885 + __t884;
            let __t986 = __t985 * __v16;
            let __t987 = __t173 * __t87;
            let __t1086 = __t1085 + __t1084;
            let __t1186 = __t1185 * __v16;
            let __t1187 = __t220 * __t87;
            let __t86 = __t85 * 0.5f64;
            let __t116 = __t102 * __t82;
            let __t122 = __t107 * __t82;
            let __t128 = __t112 * __t82;
            let __t134 = __t47 * __t87;
            let __t163 = __t161 * __v16;
            let __t166 = __t52 * __t87;
            let __t194 = __t192 * __v16;
            let __t197 = __t57 * __t87;
            let __t225 = __t223 * __v16;
            let __t229 = __t228 * __v16;
            let __t231 = __t107 * __t102;
            let __t233 = __t112 * __t102;
            let __t236 = __t235 * __v16;
            let __t238 = __t112 * __t107;
            let __t241 = __t240 * __v16;
            let __t251 = __t250 * __v16;
            let __t260 = __t259 + __t258;
            let __t270 = __t269 + __t268;
            let __t280 = __t279 + __t278;
            let __t290 = __t289 * __v16;
            let __t299 = __t298 + __t297;
            let __t309 = __t308 + __t307;
            let __t319 = __t318 + __t317;
            let __t329 = __t328 * __v16;
            let __t685 = __t682 - __t683;
            let __t786 = __t785 * __v16;
            let __t787 = __t175 * __t87;
            let __t887 = __t886 * __v16;
            let __t888 = __t208 * __t87;
            let __t989 = __t986 - __t987;
            let __t1087 = __t1086 * __v16;
            let __t1088 = __t201 * __t87;
            let __t1189 = __t1186 - __t1187;
            let __t114 = __t86 - __t88;
            let __t118 = __t116 * __v16;
            let __t124 = __t122 * __v16;
            let __t130 = __t128 * __v16;
            let __t165 = __t163 - __t134;
            let __t196 = __t194 - __t166;
            let __t227 = __t225 - __t197;
            let __t230 = __t229 + __v7;
            let __t232 = __t231 * __v16;
            let __t234 = __t233 * __v16;
            let __t237 = __t236 + __v8;
            let __t239 = __t238 * __v16;
            let __t242 = __t241 + __v9;
            let __t261 = __t260 * __v16;
            let __t271 = __t270 * __v16;
            let __t281 = __t280 * __v16;
            let __t300 = __t299 * __v16;
            let __t310 = __t309 * __v16;
            let __t320 = __t319 * __v16;
            let __t789 = __t787 + __t786;
            let __t890 = __t888 + __t887;
            let __t1090 = __t1088 + __t1087;
            let __t1804 = __t1798 * __t1785;
            let __t1806 = __t1799 * __t1785;
            let __t1808 = __t1800 * __t1785;
            let __t1832 = __t251 + __t1831;
            let __t1833 = __t1811 * __t1816;
            let __t1836 = __t1813 * __t1816;
            let __t1839 = __t1815 * __t1816;
            let __t1842 = __t1817 * __t343;
            let __t1845 = __t1817 * __t344;
            let __t1848 = __t1811 * __t1817;
            let __t1852 = __t290 + __t1851;
            let __t1853 = __t1813 * __t1817;
            let __t1856 = __t1815 * __t1817;
            let __t1859 = __t1818 * __t344;
            let __t1862 = __t1811 * __t1818;
            let __t1865 = __t1813 * __t1818;
            let __t1869 = __t329 + __t1868;
            let __t1870 = __t1815 * __t1818;
            let __t1874 = __t685 + __t1873;
            let __t1875 = __t1819 * __t1811;
            let __t1878 = __t1819 * __t1813;
            let __t1881 = __t1819 * __t1815;
            let __t1885 = __t989 + __t1884;
            let __t1886 = __t1820 * __t1813;
            let __t1889 = __t1820 * __t1815;
            let __t1893 = __t1189 + __t1892;
            let __t1894 = __t1821 * __t1815;
            let __t1790 = __t114 + __t1789;
            let __t1801 = __t118 + __t1798;
            let __t1802 = __t124 + __t1799;
            let __t1803 = __t130 + __t1800;
            let __t1805 = __t1804 + __t165;
            let __t1807 = __t1806 + __t196;
            let __t1809 = __t1808 + __t227;
            let __t1824 = __t230 - __t1822;
            let __t1827 = __t232 - __t1825;
            let __t1830 = __t234 - __t1828;
            let __t1835 = __t1832 - __t1833;
            let __t1838 = __t261 - __t1836;
            let __t1841 = __t271 - __t1839;
            let __t1844 = __t237 - __t1842;
            let __t1847 = __t239 - __t1845;
            let __t1850 = __t281 - __t1848;
            let __t1855 = __t1852 - __t1853;
            let __t1858 = __t300 - __t1856;
            let __t1861 = __t242 - __t1859;
            let __t1864 = __t310 - __t1862;
            let __t1867 = __t320 - __t1865;
            let __t1872 = __t1869 - __t1870;
            let __t1877 = __t1874 - __t1875;
            let __t1880 = __t789 - __t1878;
            let __t1883 = __t890 - __t1881;
            let __t1888 = __t1885 - __t1886;
            let __t1891 = __t1090 - __t1889;
            let __t1896 = __t1893 - __t1894;
            let __t1897 = -__t1785;
            __RouthBundle {
                routhian: __t1790,
                psi_dot: __t1785,
                dr_domega: __Vector3::new(__t1801, __t1802, __t1803),
                dr_dgamma: __Vector3::new(__t1805, __t1807, __t1809),
                dr_dp: __t1897,
                d2r_domega2: __Matrix3::new(
                    __t1824,
                    __t1827,
                    __t1830,
                    __t1827,
                    __t1844,
                    __t1847,
                    __t1830,
                    __t1847,
                    __t1861,
                ),
                d2r_domega_dgamma: __Matrix3::new(
                    __t1835,
                    __t1838,
                    __t1841,
                    __t1850,
                    __t1855,
                    __t1858,
                    __t1864,
                    __t1867,
                    __t1872,
                ),
                d2r_dgamma2: __Matrix3::new(
                    __t1877,
                    __t1880,
                    __t1883,
                    __t1880,
                    __t1888,
                    __t1891,
                    __t1883,
                    __t1891,
                    __t1896,
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
            let __t342 = __v7 * __v3;
            let __t343 = __v8 * __v4;
            let __t344 = __v9 * __v5;
            let __t87 = __v17 * __v16;
            let __t22 = __t18 * __v3;
            let __t23 = __t19 * __v4;
            let __t24 = __t20 * __v5;
            let __t345 = __t342 * __v3;
            let __t346 = __t343 * __v4;
            let __t347 = __t344 * __v5;
            let __t25 = __t22 * __v3;
            let __t26 = __t23 * __v4;
            let __t27 = __t24 * __v5;
            let __t348 = __t346 + __t345;
            let __t28 = __t26 + __t25;
            let __t349 = __t348 + __t347;
            let __t29 = __t28 + __t27;
            let __t359 = 1.0f64 / __t349;
            let __t30 = __t29.sqrt();
            let __t1251 = __t359 * __v6;
            let __t1816 = __t359 * __t342;
            let __t1817 = __t359 * __t343;
            let __t1818 = __t359 * __t344;
            let __t1258 = __t1251 * __t342;
            let __t1259 = __t1251 * __t343;
            let __t1260 = __t1251 * __t344;
            let __t1336 = __t1251 * __v7;
            let __t1368 = __t1251 * __v8;
            let __t43 = 1.0f64 / __t30;
            let __t1393 = __t1251 * __v9;
            let __t1822 = __t1816 * __t342;
            let __t1264 = __t1258 * __t1251;
            let __t1266 = __t1259 * __t1251;
            let __t1268 = __t1260 * __t1251;
            let __t1273 = __t1258 * __t359;
            let __t1275 = __t1259 * __t359;
            let __t1277 = __t1260 * __t359;
            let __t1337 = __t1336 * __t1251;
            let __t1369 = __t1368 * __t1251;
            let __t1394 = __t1393 * __t1251;
            let __t1958 = __t1258 * __t1816;
            let __t1971 = __t1259 * __t1817;
            let __t1339 = __t1273 * __t1258;
            let __t1371 = __t1275 * __t1259;
            let __t1396 = __t1277 * __t1260;
            let __t1346 = __t1273 * __t1259;
            let __t1351 = __t1273 * __t1260;
            let __t1376 = __t1275 * __t1260;
            let __t1960 = __t1958 * (-2f64);
            let __t1973 = __t1971 * (-2f64);
            let __t1344 = __t1339 * (-4f64);
            let __t1374 = __t1371 * (-4f64);
            let __t1399 = __t1396 * (-4f64);
            let __t1984 = __t1260 * __t1818;
            let __t1349 = __t1346 * (-4f64);
            let __t1354 = __t1351 * (-4f64);
            let __t45 = __t43 * __t22;
            let __t50 = __t43 * __t23;
            let __t55 = __t43 * __t24;
            let __t137 = __t43 * __t43;
            let __t148 = __t43 * __t18;
            let __t170 = __t43 * __t19;
            let __t217 = __t43 * __t20;
            let __t1379 = __t1376 * (-4f64);
            let __t47 = __t45 - __v13;
            let __t52 = __t50 - __v14;
            let __t57 = __t55 - __v15;
            let __t138 = __t137 * __t45;
            let __t168 = __t137 * __t50;
            let __t199 = __t137 * __t55;
            let __t1961 = __t1960 + __t1336;
            let __t1974 = __t1973 + __t1368;
            let __t134 = __t47 * __t87;
            let __t166 = __t52 * __t87;
            let __t197 = __t57 * __t87;
            let __t149 = __t138 * __t22;
            let __t171 = __t168 * __t23;
            let __t218 = __t199 * __t24;
            let __t175 = __t168 * __t22;
            let __t201 = __t199 * __t23;
            let __t1265 = __t1264 - __t134;
            let __t1267 = __t1266 - __t166;
            let __t1269 = __t1268 - __t197;
            let __t151 = __t148 - __t149;
            let __t173 = __t170 - __t171;
            let __t220 = __t217 - __t218;
            let __t208 = __t199 * __t22;
            let __t98 = __t52 * __v5;
            let __t1411 = __t1265 * __v3;
            let __t1412 = __t1267 * __v4;
            let __t1413 = __t1269 * __v5;
            let __t683 = __t151 * __t87;
            let __t987 = __t173 * __t87;
            let __t1187 = __t220 * __t87;
            let __t100 = __t57 * __v4;
            let __t104 = __t47 * __v5;
            let __t106 = __t57 * __v3;
            let __t1414 = __t1412 + __t1411;
            let __t109 = __t52 * __v3;
            let __t1338 = __t1337 - __t683;
            let __t1370 = __t1369 - __t987;
            let __t1395 = __t1394 - __t1187;
            let __t111 = __t47 * __v4;
            let __t787 = __t175 * __t87;
            let __t888 = __t208 * __t87;
            let __t1088 = __t201 * __t87;
            let __t1415 = __t1414 + __t1413;
            let __t1345 = __t1338 + __t1344;
            let __t1375 = __t1370 + __t1374;
            let __t1400 = __t1395 + __t1399;
            let __t1986 = __t1984 * (-2f64);
            let __t102 = __t98 - __t100;
            let __t107 = __t106 - __t104;
            let __t112 = __t111 - __t109;
            let __t1350 = __t787 + __t1349;
            let __t1355 = __t888 + __t1354;
            let __t1380 = __t1088 + __t1379;
            let __t1417 = __t1345 - __t1415;
            let __t1418 = __t1375 - __t1415;
            let __t1419 = __t1400 - __t1415;
            let __t1987 = __t1986 + __t1393;
            let __t1988 = __t1974 + __t1961;
            let __t228 = __t102 * __t102;
            let __t235 = __t107 * __t107;
            let __t240 = __t112 * __t112;
            let __t1420 = __t1380 * __v5;
            let __t1424 = __t1418 * __v5;
            let __t1421 = __t1419 * __v4;
            let __t1425 = __t1380 * __v4;
            let __t1432 = __t1419 * __v3;
            let __t1433 = __t1355 * __v5;
            let __t1436 = __t1380 * __v3;
            let __t1437 = __t1350 * __v5;
            let __t1444 = __t1355 * __v4;
            let __t1447 = __t1350 * __v4;
            let __t1448 = __t1418 * __v3;
            let __t1455 = __t1355 * __v3;
            let __t1456 = __t1417 * __v5;
            let __t1463 = __t1417 * __v4;
            let __t1464 = __t1350 * __v3;
            let __t1989 = __t1988 + __t1987;
            let __t229 = __t228 * __v16;
            let __t231 = __t107 * __t102;
            let __t233 = __t112 * __t102;
            let __t236 = __t235 * __v16;
            let __t238 = __t112 * __t107;
            let __t241 = __t240 * __v16;
            let __t1423 = __t1420 - __t1421;
            let __t1427 = __t1424 - __t1425;
            let __t1435 = __t1432 - __t1433;
            let __t1439 = __t1436 - __t1437;
            let __t1446 = __t1444 - __t1436;
            let __t1450 = __t1447 - __t1448;
            let __t1458 = __t1455 - __t1456;
            let __t1466 = __t1463 - __t1464;
            let __t1990 = __t1989 * 0.5f64;
            let __t230 = __t229 + __v7;
            let __t232 = __t231 * __v16;
            let __t234 = __t233 * __v16;
            let __t237 = __t236 + __v8;
            let __t239 = __t238 * __v16;
            let __t242 = __t241 + __v9;
            let __t1428 = __t1423 * __v4;
            let __t1429 = __t1427 * __v5;
            let __t1440 = __t1435 * __v4;
            let __t1441 = __t1439 * __v5;
            let __t1451 = __t1446 * __v4;
            let __t1452 = __t1450 * __v5;
            let __t1459 = __t1458 * __v5;
            let __t1460 = __t1435 * __v3;
            let __t1467 = __t1466 * __v5;
            let __t1468 = __t1446 * __v3;
            let __t1471 = __t1450 * __v3;
            let __t1472 = __t1466 * __v4;
            let __t1825 = __t1816 * __t343;
            let __t1828 = __t1816 * __t344;
            let __t1842 = __t1817 * __t343;
            let __t1845 = __t1817 * __t344;
            let __t1859 = __t1818 * __t344;
            let __t1991 = __t1990 * __v3;
            let __t1992 = __t1990 * __v4;
            let __t1993 = __t1990 * __v5;
            let __t1431 = __t1428 - __t1429;
            let __t1443 = __t1440 - __t1441;
            let __t1454 = __t1451 - __t1452;
            let __t1462 = __t1459 - __t1460;
            let __t1470 = __t1467 - __t1468;
            let __t1474 = __t1471 - __t1472;
            let __t1824 = __t230 - __t1822;
            let __t1827 = __t232 - __t1825;
            let __t1830 = __t234 - __t1828;
            let __t1844 = __t237 - __t1842;
            let __t1847 = __t239 - __t1845;
            let __t1861 = __t242 - __t1859;
            let __t1994 = -__t1991;
            let __t1995 = -__t1992;
            let __t1996 = -__t1993;
            __GyroscopicSystem {
                a: __Matrix3::new(
                    __t1824,
                    __t1827,
                    __t1830,
                    __t1827,
                    __t1844,
                    __t1847,
                    __t1830,
                    __t1847,
                    __t1861,
                ),
                g: __Matrix3::new(
                    0f64,
                    __t1996,
                    __t1992,
                    __t1993,
                    0f64,
                    __t1994,
                    __t1995,
                    __t1991,
                    0f64,
                ),
                c: __Matrix3::new(
                    __t1431,
                    __t1443,
                    __t1454,
                    __t1443,
                    __t1462,
                    __t1470,
                    __t1454,
                    __t1470,
                    __t1474,
                ),
            }
        }
        #[inline]
        fn bundle_and_system(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> (__RouthBundle, __GyroscopicSystem) {
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
            let __t342 = __v7 * __v3;
            let __t343 = __v8 * __v4;
            let __t58 = __v7 * __v0;
            let __t59 = __v8 * __v1;
            let __t344 = __v9 * __v5;
            let __t22 = __t18 * __v3;
            let __t23 = __t19 * __v4;
            let __t24 = __t20 * __v5;
            let __t345 = __t342 * __v3;
            let __t346 = __t343 * __v4;
            let __t60 = __v9 * __v2;
            let __t1771 = __t59 * __v4;
            let __t1772 = __t343 * __v1;
            let __t25 = __t22 * __v3;
            let __t26 = __t23 * __v4;
            let __t27 = __t24 * __v5;
            let __t1774 = __t58 * __v3;
            let __t1775 = __t342 * __v0;
            let __t347 = __t344 * __v5;
            let __t348 = __t346 + __t345;
            let __t66 = __v4 * __v2;
            let __t67 = __v5 * __v1;
            let __t28 = __t26 + __t25;
            let __t70 = __v5 * __v0;
            let __t71 = __v3 * __v2;
            let __t1773 = __t1772 + __t1771;
            let __t1776 = __t1775 + __t1774;
            let __t1778 = __t60 * __v5;
            let __t1779 = __t344 * __v2;
            let __t349 = __t348 + __t347;
            let __t29 = __t28 + __t27;
            let __t69 = __t66 - __t67;
            let __t73 = __t70 - __t71;
            let __t74 = __v3 * __v1;
            let __t75 = __v4 * __v0;
            let __t1777 = __t1776 + __t1773;
            let __t1780 = __t1779 + __t1778;
            let __t359 = 1.0f64 / __t349;
            let __t30 = __t29.sqrt();
            let __t87 = __v17 * __v16;
            let __t404 = __t342 * 2f64;
            let __t405 = __t343 * 2f64;
            let __t77 = __t74 - __t75;
            let __t406 = __t344 * 2f64;
            let __t1781 = __t1780 + __t1777;
            let __t31 = __v13 * __v3;
            let __t32 = __v14 * __v4;
            let __t61 = __t58 * __v0;
            let __t62 = __t59 * __v1;
            let __t33 = __v15 * __v5;
            let __t63 = __t60 * __v2;
            let __t1783 = __t1781 * (-0.5f64);
            let __t34 = __t32 + __t31;
            let __t64 = __t62 + __t61;
            let __t1784 = __t1783 + __v6;
            let __t35 = __t34 + __t33;
            let __t65 = __t64 + __t63;
            let __t1816 = __t359 * __t342;
            let __t1817 = __t359 * __t343;
            let __t1818 = __t359 * __t344;
            let __t1785 = __t1784 * __t359;
            let __t1822 = __t1816 * __t342;
            let __t43 = 1.0f64 / __t30;
            let __t37 = __t30 - __t35;
            let __t1795 = __t1785 * __t342;
            let __t1796 = __t1785 * __t343;
            let __t1797 = __t1785 * __t344;
            let __t1810 = __t1785 * __t404;
            let __t1812 = __t1785 * __t405;
            let __t1814 = __t1785 * __t406;
            let __t1831 = __t1785 * __v7;
            let __t1851 = __t1785 * __v8;
            let __t1798 = __t1795 + __t58;
            let __t1799 = __t1796 + __t59;
            let __t1800 = __t1797 + __t60;
            let __t1811 = __t1810 + __t58;
            let __t1813 = __t1812 + __t59;
            let __t1815 = __t1814 + __t60;
            let __t1868 = __t1785 * __v9;
            let __t1873 = __t1831 * __t1785;
            let __t1804 = __t1798 * __t1785;
            let __t1806 = __t1799 * __t1785;
            let __t1808 = __t1800 * __t1785;
            let __t1819 = __t1811 * __t359;
            let __t1820 = __t1813 * __t359;
            let __t1821 = __t1815 * __t359;
            let __t1884 = __t1851 * __t1785;
            let __t1892 = __t1868 * __t1785;
            let __t1833 = __t1811 * __t1816;
            let __t1853 = __t1813 * __t1817;
            let __t45 = __t43 * __t22;
            let __t50 = __t43 * __t23;
            let __t55 = __t43 * __t24;
            let __t137 = __t43 * __t43;
            let __t148 = __t43 * __t18;
            let __t170 = __t43 * __t19;
            let __t217 = __t43 * __t20;
            let __t1875 = __t1819 * __t1811;
            let __t47 = __t45 - __v13;
            let __t52 = __t50 - __v14;
            let __t57 = __t55 - __v15;
            let __t138 = __t137 * __t45;
            let __t168 = __t137 * __t50;
            let __t199 = __t137 * __t55;
            let __t1886 = __t1820 * __t1813;
            let __t1894 = __t1821 * __t1815;
            let __t179 = __t47 * __v2;
            let __t144 = __t52 * __v2;
            let __t78 = __t47 * __t69;
            let __t149 = __t138 * __t22;
            let __t171 = __t168 * __t23;
            let __t218 = __t199 * __t24;
            let __t641 = __t138 * __t43;
            let __t748 = __t168 * __t43;
            let __t847 = __t199 * __t43;
            let __t175 = __t168 * __t22;
            let __t201 = __t199 * __t23;
            let __t151 = __t148 - __t149;
            let __t173 = __t170 - __t171;
            let __t220 = __t217 - __t218;
            let __t646 = __t641 * __t45;
            let __t950 = __t748 * __t50;
            let __t1148 = __t847 * __t55;
            let __t208 = __t199 * __t22;
            let __t753 = __t748 * __t45;
            let __t645 = __t151 * __t137;
            let __t852 = __t847 * __t45;
            let __t949 = __t173 * __t137;
            let __t647 = __t646 * (-2f64);
            let __t951 = __t950 * (-2f64);
            let __t1053 = __t847 * __t50;
            let __t1147 = __t220 * __t137;
            let __t1149 = __t1148 * (-2f64);
            let __t140 = __t138 * __t23;
            let __t656 = __t138 * __t18;
            let __t751 = __t175 * __t137;
            let __t648 = __t647 + __t645;
            let __t754 = __t753 * (-2f64);
            let __t850 = __t208 * __t137;
            let __t853 = __t852 * (-2f64);
            let __t952 = __t951 + __t949;
            let __t968 = __t168 * __t19;
            let __t1051 = __t201 * __t137;
            let __t1054 = __t1053 * (-2f64);
            let __t1150 = __t1149 + __t1147;
            let __t142 = __t140 * __t73;
            let __t154 = __t138 * __t24;
            let __t177 = __t175 * __t69;
            let __t183 = __t168 * __t24;
            let __t657 = __t648 * __t22;
            let __t661 = __t656 * 2f64;
            let __t666 = __t140 * __v2;
            let __t668 = __t648 * __t23;
            let __t755 = __t754 - __t751;
            let __t854 = __t853 - __t850;
            let __t959 = __t175 * __v2;
            let __t961 = __t952 * __t22;
            let __t969 = __t952 * __t23;
            let __t973 = __t968 * 2f64;
            let __t1055 = __t1054 - __t1051;
            let __t1151 = __t199 * __t20;
            let __t1161 = __t208 * __v1;
            let __t1163 = __t1150 * __t22;
            let __t1169 = __t201 * __v0;
            let __t1171 = __t1150 * __t23;
            let __t79 = __t52 * __t73;
            let __t146 = __t142 + __t144;
            let __t152 = __t151 * __t69;
            let __t156 = __t154 * __t77;
            let __t158 = __t57 * __v1;
            let __t174 = __t173 * __t73;
            let __t180 = __t179 - __t177;
            let __t185 = __t183 * __t77;
            let __t187 = __t57 * __v0;
            let __t203 = __t201 * __t73;
            let __t205 = __t52 * __v0;
            let __t210 = __t208 * __t69;
            let __t212 = __t47 * __v1;
            let __t638 = __t154 * __v1;
            let __t649 = __t648 * __t24;
            let __t662 = __t661 + __t657;
            let __t669 = __t668 * __t73;
            let __t671 = __t666 * (-2f64);
            let __t764 = __t755 * __t22;
            let __t766 = __t168 * __t18;
            let __t775 = __t138 * __t19;
            let __t776 = __t755 * __t23;
            let __t861 = __t854 * __t22;
            let __t863 = __t199 * __t18;
            let __t875 = __t854 * __t23;
            let __t947 = __t183 * __v0;
            let __t953 = __t952 * __t24;
            let __t962 = __t961 * __t69;
            let __t965 = __t959 * 2f64;
            let __t974 = __t973 + __t969;
            let __t1064 = __t1055 * __t22;
            let __t1072 = __t1055 * __t23;
            let __t1074 = __t199 * __t19;
            let __t1152 = __t1150 * __t24;
            let __t1156 = __t1151 * 2f64;
            let __t1164 = __t1163 * __t69;
            let __t1166 = __t1161 * (-2f64);
            let __t1172 = __t1171 * __t73;
            let __t1175 = __t1169 * 2f64;
            let __t80 = __t57 * __t77;
            let __t81 = __t79 + __t78;
            let __t153 = __t152 - __t146;
            let __t159 = __t158 - __t156;
            let __t181 = __t180 + __t174;
            let __t189 = __t187 + __t185;
            let __t206 = __t205 - __t203;
            let __t214 = __t212 + __t210;
            let __t650 = __t649 * __t77;
            let __t653 = __t638 * 2f64;
            let __t664 = __t662 * __t69;
            let __t672 = __t671 + __t669;
            let __t756 = __t755 * __t24;
            let __t768 = __t766 + __t764;
            let __t777 = __t776 + __t775;
            let __t855 = __t138 * __t20;
            let __t856 = __t854 * __t24;
            let __t865 = __t863 + __t861;
            let __t876 = __t140 * __v0;
            let __t877 = __t875 * __t73;
            let __t954 = __t953 * __t77;
            let __t956 = __t947 * (-2f64);
            let __t966 = __t965 + __t962;
            let __t976 = __t974 * __t73;
            let __t1056 = __t168 * __t20;
            let __t1057 = __t1055 * __t24;
            let __t1065 = __t175 * __v1;
            let __t1067 = __t1064 * __t69;
            let __t1076 = __t1074 + __t1072;
            let __t1157 = __t1156 + __t1152;
            let __t1167 = __t1166 + __t1164;
            let __t1176 = __t1175 + __t1172;
            let __t82 = __t81 + __t80;
            let __t160 = __t159 + __t153;
            let __t191 = __t181 - __t189;
            let __t216 = __t206 - __t214;
            let __t221 = __t220 * __t77;
            let __t654 = __t653 + __t650;
            let __t674 = __t672 + __t664;
            let __t757 = __t154 * __v0;
            let __t759 = __t756 * __t77;
            let __t770 = __t151 * __v2;
            let __t771 = __t768 * __t69;
            let __t774 = __t173 * __v2;
            let __t778 = __t777 * __t73;
            let __t857 = __t856 + __t855;
            let __t867 = __t151 * __v1;
            let __t869 = __t865 * __t69;
            let __t873 = __t201 * __v2;
            let __t878 = __t877 + __t876;
            let __t957 = __t956 + __t954;
            let __t978 = __t976 + __t966;
            let __t1058 = __t1057 + __t1056;
            let __t1062 = __t208 * __v2;
            let __t1068 = __t1067 - __t1065;
            let __t1078 = __t173 * __v0;
            let __t1079 = __t1076 * __t73;
            let __t1159 = __t1157 * __t77;
            let __t1178 = __t1176 + __t1167;
            let __t161 = __t160 * __t82;
            let __t192 = __t191 * __t82;
            let __t222 = __t221 + __t216;
            let __t676 = __t674 + __t654;
            let __t746 = __t183 * __v1;
            let __t760 = __t759 - __t757;
            let __t773 = __t770 - __t771;
            let __t779 = __t778 + __t774;
            let __t846 = __t220 * __v1;
            let __t858 = __t857 * __t77;
            let __t871 = __t869 + __t867;
            let __t879 = __t878 - __t873;
            let __t980 = __t978 + __t957;
            let __t1050 = __t220 * __v0;
            let __t1059 = __t1058 * __t77;
            let __t1070 = __t1068 + __t1062;
            let __t1081 = __t1078 - __t1079;
            let __t1180 = __t1178 + __t1159;
            let __t98 = __t52 * __v5;
            let __t100 = __t57 * __v4;
            let __t104 = __t47 * __v5;
            let __t106 = __t57 * __v3;
            let __t243 = __t154 * __v4;
            let __t245 = __t140 * __v5;
            let __t282 = __t183 * __v3;
            let __t284 = __t175 * __v5;
            let __t134 = __t47 * __t87;
            let __t163 = __t161 * __v16;
            let __t166 = __t52 * __t87;
            let __t194 = __t192 * __v16;
            let __t223 = __t222 * __t82;
            let __t678 = __t160 * __t160;
            let __t679 = __t676 * __t82;
            let __t762 = __t760 + __t746;
            let __t781 = __t773 - __t779;
            let __t860 = __t846 - __t858;
            let __t881 = __t879 + __t871;
            let __t982 = __t191 * __t191;
            let __t983 = __t980 * __t82;
            let __t1060 = __t1059 + __t1050;
            let __t1082 = __t1081 - __t1070;
            let __t1182 = __t222 * __t222;
            let __t1183 = __t1180 * __t82;
            let __t102 = __t98 - __t100;
            let __t107 = __t106 - __t104;
            let __t109 = __t52 * __v3;
            let __t111 = __t47 * __v4;
            let __t247 = __t243 - __t245;
            let __t286 = __t284 - __t282;
            let __t321 = __t208 * __v4;
            let __t323 = __t201 * __v3;
            let __t165 = __t163 - __t134;
            let __t196 = __t194 - __t166;
            let __t197 = __t57 * __t87;
            let __t225 = __t223 * __v16;
            let __t681 = __t678 - __t679;
            let __t782 = __t781 - __t762;
            let __t883 = __t860 - __t881;
            let __t985 = __t982 - __t983;
            let __t1083 = __t1082 - __t1060;
            let __t1185 = __t1182 - __t1183;
            let __t112 = __t111 - __t109;
            let __t248 = __t102 * __t160;
            let __t249 = __t247 * __t82;
            let __t287 = __t107 * __t191;
            let __t288 = __t286 * __t82;
            let __t325 = __t323 - __t321;
            let __t227 = __t225 - __t197;
            let __t682 = __t681 * __v16;
            let __t683 = __t151 * __t87;
            let __t783 = __t191 * __t160;
            let __t784 = __t782 * __t82;
            let __t884 = __t222 * __t160;
            let __t885 = __t883 * __t82;
            let __t986 = __t985 * __v16;
            let __t987 = __t173 * __t87;
            let __t1084 = __t222 * __t191;
            let __t1085 = __t1083 * __t82;
            let __t1186 = __t1185 * __v16;
            let __t1187 = __t220 * __t87;
            let __t1805 = __t165 + __t1804;
            let __t1807 = __t196 + __t1806;
            let __t250 = __t249 + __t248;
            let __t289 = __t288 + __t287;
            let __t326 = __t112 * __t222;
            let __t327 = __t325 * __t82;
            let __t685 = __t682 - __t683;
            let __t785 = __t784 + __t783;
            let __t886 = __t885 + __t884;
            let __t989 = __t986 - __t987;
            let __t1086 = __t1085 + __t1084;
            let __t1189 = __t1186 - __t1187;
            let __t1809 = __t227 + __t1808;
            let __t251 = __t250 * __v16;
            let __t290 = __t289 * __v16;
            let __t328 = __t327 + __t326;
            let __t252 = __t183 * __v4;
            let __t264 = __t201 * __v5;
            let __t272 = __t154 * __v3;
            let __t292 = __t208 * __v5;
            let __t302 = __t140 * __v3;
            let __t311 = __t175 * __v4;
            let __t786 = __t785 * __v16;
            let __t787 = __t175 * __t87;
            let __t887 = __t886 * __v16;
            let __t888 = __t208 * __t87;
            let __t1087 = __t1086 * __v16;
            let __t1088 = __t201 * __t87;
            let __t1874 = __t685 + __t1873;
            let __t1885 = __t989 + __t1884;
            let __t1893 = __t1189 + __t1892;
            let __t329 = __t328 * __v16;
            let __t1832 = __t251 + __t1831;
            let __t1852 = __t290 + __t1851;
            let __t83 = __t82 * __t82;
            let __t254 = __t57 - __t252;
            let __t256 = __t173 * __v5;
            let __t262 = __t220 * __v4;
            let __t266 = __t52 - __t264;
            let __t274 = __t57 - __t272;
            let __t275 = __t151 * __v5;
            let __t291 = __t220 * __v3;
            let __t294 = __t47 - __t292;
            let __t301 = __t151 * __v4;
            let __t304 = __t52 - __t302;
            let __t313 = __t47 - __t311;
            let __t314 = __t173 * __v3;
            let __t789 = __t787 + __t786;
            let __t890 = __t888 + __t887;
            let __t1090 = __t1088 + __t1087;
            let __t1877 = __t1874 - __t1875;
            let __t1878 = __t1819 * __t1813;
            let __t1881 = __t1819 * __t1815;
            let __t1888 = __t1885 - __t1886;
            let __t1889 = __t1820 * __t1815;
            let __t1896 = __t1893 - __t1894;
            let __t1835 = __t1832 - __t1833;
            let __t1855 = __t1852 - __t1853;
            let __t1869 = __t329 + __t1868;
            let __t1870 = __t1815 * __t1818;
            let __t84 = __t83 * __v16;
            let __t257 = __t256 - __t254;
            let __t267 = __t266 - __t262;
            let __t277 = __t274 - __t275;
            let __t296 = __t291 - __t294;
            let __t306 = __t301 - __t304;
            let __t316 = __t313 - __t314;
            let __t1880 = __t789 - __t1878;
            let __t1883 = __t890 - __t1881;
            let __t1891 = __t1090 - __t1889;
            let __t1872 = __t1869 - __t1870;
            let __t85 = __t84 + __t65;
            let __t228 = __t102 * __t102;
            let __t235 = __t107 * __t107;
            let __t240 = __t112 * __t112;
            let __t258 = __t102 * __t191;
            let __t259 = __t257 * __t82;
            let __t268 = __t102 * __t222;
            let __t269 = __t267 * __t82;
            let __t278 = __t107 * __t160;
            let __t279 = __t277 * __t82;
            let __t297 = __t107 * __t222;
            let __t298 = __t296 * __t82;
            let __t307 = __t112 * __t160;
            let __t308 = __t306 * __t82;
            let __t317 = __t112 * __t191;
            let __t318 = __t316 * __t82;
            let __t86 = __t85 * 0.5f64;
            let __t88 = __t37 * __t87;
            let __t116 = __t102 * __t82;
            let __t122 = __t107 * __t82;
            let __t128 = __t112 * __t82;
            let __t229 = __t228 * __v16;
            let __t231 = __t107 * __t102;
            let __t233 = __t112 * __t102;
            let __t236 = __t235 * __v16;
            let __t238 = __t112 * __t107;
            let __t241 = __t240 * __v16;
            let __t260 = __t259 + __t258;
            let __t270 = __t269 + __t268;
            let __t280 = __t279 + __t278;
            let __t299 = __t298 + __t297;
            let __t309 = __t308 + __t307;
            let __t319 = __t318 + __t317;
            let __t1787 = __t1785 * __t1784;
            let __t114 = __t86 - __t88;
            let __t118 = __t116 * __v16;
            let __t124 = __t122 * __v16;
            let __t130 = __t128 * __v16;
            let __t230 = __t229 + __v7;
            let __t232 = __t231 * __v16;
            let __t234 = __t233 * __v16;
            let __t237 = __t236 + __v8;
            let __t239 = __t238 * __v16;
            let __t242 = __t241 + __v9;
            let __t261 = __t260 * __v16;
            let __t271 = __t270 * __v16;
            let __t281 = __t280 * __v16;
            let __t300 = __t299 * __v16;
            let __t310 = __t309 * __v16;
            let __t320 = __t319 * __v16;
            let __t1789 = __t1787 * (-0.5f64);
            let __t1825 = __t1816 * __t343;
            let __t1828 = __t1816 * __t344;
            let __t1836 = __t1813 * __t1816;
            let __t1839 = __t1815 * __t1816;
            let __t1842 = __t1817 * __t343;
            let __t1845 = __t1817 * __t344;
            let __t1848 = __t1811 * __t1817;
            let __t1856 = __t1815 * __t1817;
            let __t1859 = __t1818 * __t344;
            let __t1862 = __t1811 * __t1818;
            let __t1865 = __t1813 * __t1818;
            let __t1790 = __t1789 + __t114;
            let __t1801 = __t118 + __t1798;
            let __t1802 = __t124 + __t1799;
            let __t1803 = __t130 + __t1800;
            let __t1824 = __t230 - __t1822;
            let __t1827 = __t232 - __t1825;
            let __t1830 = __t234 - __t1828;
            let __t1838 = __t261 - __t1836;
            let __t1841 = __t271 - __t1839;
            let __t1844 = __t237 - __t1842;
            let __t1847 = __t239 - __t1845;
            let __t1850 = __t281 - __t1848;
            let __t1858 = __t300 - __t1856;
            let __t1861 = __t242 - __t1859;
            let __t1864 = __t310 - __t1862;
            let __t1867 = __t320 - __t1865;
            let __t1897 = -__t1785;
            let __bundle = __RouthBundle {
                routhian: __t1790,
                psi_dot: __t1785,
                dr_domega: __Vector3::new(__t1801, __t1802, __t1803),
                dr_dgamma: __Vector3::new(__t1805, __t1807, __t1809),
                dr_dp: __t1897,
                d2r_domega2: __Matrix3::new(
                    __t1824,
                    __t1827,
                    __t1830,
                    __t1827,
                    __t1844,
                    __t1847,
                    __t1830,
                    __t1847,
                    __t1861,
                ),
                d2r_domega_dgamma: __Matrix3::new(
                    __t1835,
                    __t1838,
                    __t1841,
                    __t1850,
                    __t1855,
                    __t1858,
                    __t1864,
                    __t1867,
                    __t1872,
                ),
                d2r_dgamma2: __Matrix3::new(
                    __t1877,
                    __t1880,
                    __t1883,
                    __t1880,
                    __t1888,
                    __t1891,
                    __t1883,
                    __t1891,
                    __t1896,
                ),
            };
            let __t2006 = __t1805 * __v3;
            let __t2007 = __t1807 * __v4;
            let __t2008 = __t1809 * __v5;
            let __t1997 = __t1855 + __t1835;
            let __t2015 = __t1891 * __v5;
            let __t2020 = __t1891 * __v4;
            let __t2028 = __t1883 * __v5;
            let __t2031 = __t1891 * __v3;
            let __t2032 = __t1880 * __v5;
            let __t2009 = __t2007 + __t2006;
            let __t2039 = __t1883 * __v4;
            let __t2042 = __t1880 * __v4;
            let __t2050 = __t1883 * __v3;
            let __t2059 = __t1880 * __v3;
            let __t1998 = __t1997 + __t1872;
            let __t2034 = __t2031 - __t2032;
            let __t2010 = __t2009 + __t2008;
            let __t2041 = __t2039 - __t2031;
            let __t1999 = __t1998 * 0.5f64;
            let __t2036 = __t2034 * __v5;
            let __t2012 = __t1877 - __t2010;
            let __t2013 = __t1888 - __t2010;
            let __t2014 = __t1896 - __t2010;
            let __t2046 = __t2041 * __v4;
            let __t2063 = __t2041 * __v3;
            let __t2000 = __t1999 * __v3;
            let __t2001 = __t1999 * __v4;
            let __t2002 = __t1999 * __v5;
            let __t2051 = __t2012 * __v5;
            let __t2019 = __t2013 * __v5;
            let __t2016 = __t2014 * __v4;
            let __t2027 = __t2014 * __v3;
            let __t2043 = __t2013 * __v3;
            let __t2058 = __t2012 * __v4;
            let __t2003 = -__t2000;
            let __t2004 = -__t2001;
            let __t2053 = __t2050 - __t2051;
            let __t2022 = __t2019 - __t2020;
            let __t2018 = __t2015 - __t2016;
            let __t2030 = __t2027 - __t2028;
            let __t2045 = __t2042 - __t2043;
            let __t2061 = __t2058 - __t2059;
            let __t2005 = -__t2002;
            let __t2054 = __t2053 * __v5;
            let __t2024 = __t2022 * __v5;
            let __t2023 = __t2018 * __v4;
            let __t2035 = __t2030 * __v4;
            let __t2047 = __t2045 * __v5;
            let __t2055 = __t2030 * __v3;
            let __t2062 = __t2061 * __v5;
            let __t2066 = __t2045 * __v3;
            let __t2067 = __t2061 * __v4;
            let __t2026 = __t2023 - __t2024;
            let __t2038 = __t2035 - __t2036;
            let __t2049 = __t2046 - __t2047;
            let __t2057 = __t2054 - __t2055;
            let __t2065 = __t2062 - __t2063;
            let __t2069 = __t2066 - __t2067;
            (
                __bundle,
                __GyroscopicSystem {
                    a: __Matrix3::new(
                        __t1824,
                        __t1827,
                        __t1830,
                        __t1827,
                        __t1844,
                        __t1847,
                        __t1830,
                        __t1847,
                        __t1861,
                    ),
                    g: __Matrix3::new(
                        0f64,
                        __t2005,
                        __t2001,
                        __t2002,
                        0f64,
                        __t2003,
                        __t2004,
                        __t2000,
                        0f64,
                    ),
                    c: __Matrix3::new(
                        __t2026,
                        __t2038,
                        __t2049,
                        __t2038,
                        __t2057,
                        __t2065,
                        __t2049,
                        __t2065,
                        __t2069,
                    ),
                },
            )
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
            let __t342 = __v7 * __v3;
            let __t343 = __v8 * __v4;
            let __t58 = __v7 * __v0;
            let __t59 = __v8 * __v1;
            let __t344 = __v9 * __v5;
            let __t22 = __t18 * __v3;
            let __t23 = __t19 * __v4;
            let __t24 = __t20 * __v5;
            let __t345 = __t342 * __v3;
            let __t346 = __t343 * __v4;
            let __t60 = __v9 * __v2;
            let __t66 = __v4 * __v2;
            let __t67 = __v5 * __v1;
            let __t25 = __t22 * __v3;
            let __t26 = __t23 * __v4;
            let __t27 = __t24 * __v5;
            let __t70 = __v5 * __v0;
            let __t71 = __v3 * __v2;
            let __t1771 = __t59 * __v4;
            let __t1772 = __t343 * __v1;
            let __t1774 = __t58 * __v3;
            let __t1775 = __t342 * __v0;
            let __t28 = __t26 + __t25;
            let __t347 = __t344 * __v5;
            let __t348 = __t346 + __t345;
            let __t69 = __t66 - __t67;
            let __t73 = __t70 - __t71;
            let __t74 = __v3 * __v1;
            let __t75 = __v4 * __v0;
            let __t1773 = __t1772 + __t1771;
            let __t29 = __t28 + __t27;
            let __t1776 = __t1775 + __t1774;
            let __t1778 = __t60 * __v5;
            let __t1779 = __t344 * __v2;
            let __t349 = __t348 + __t347;
            let __t404 = __t342 * 2f64;
            let __t77 = __t74 - __t75;
            let __t405 = __t343 * 2f64;
            let __t30 = __t29.sqrt();
            let __t1777 = __t1776 + __t1773;
            let __t87 = __v17 * __v16;
            let __t1780 = __t1779 + __t1778;
            let __t359 = 1.0f64 / __t349;
            let __t406 = __t344 * 2f64;
            let __t1781 = __t1780 + __t1777;
            let __t1783 = __t1781 * (-0.5f64);
            let __t1784 = __t1783 + __v6;
            let __t1816 = __t359 * __t342;
            let __t1817 = __t359 * __t343;
            let __t1818 = __t359 * __t344;
            let __t1785 = __t1784 * __t359;
            let __t43 = 1.0f64 / __t30;
            let __t1795 = __t1785 * __t342;
            let __t1796 = __t1785 * __t343;
            let __t1797 = __t1785 * __t344;
            let __t1810 = __t1785 * __t404;
            let __t1812 = __t1785 * __t405;
            let __t1814 = __t1785 * __t406;
            let __t1831 = __t1785 * __v7;
            let __t1851 = __t1785 * __v8;
            let __t1798 = __t1795 + __t58;
            let __t1799 = __t1796 + __t59;
            let __t1800 = __t1797 + __t60;
            let __t1811 = __t1810 + __t58;
            let __t1813 = __t1812 + __t59;
            let __t1815 = __t1814 + __t60;
            let __t1868 = __t1785 * __v9;
            let __t1804 = __t1798 * __t1785;
            let __t1806 = __t1799 * __t1785;
            let __t1808 = __t1800 * __t1785;
            let __t1833 = __t1811 * __t1816;
            let __t1836 = __t1813 * __t1816;
            let __t45 = __t43 * __t22;
            let __t50 = __t43 * __t23;
            let __t137 = __t43 * __t43;
            let __t55 = __t43 * __t24;
            let __t148 = __t43 * __t18;
            let __t170 = __t43 * __t19;
            let __t217 = __t43 * __t20;
            let __t1848 = __t1811 * __t1817;
            let __t47 = __t45 - __v13;
            let __t52 = __t50 - __v14;
            let __t138 = __t137 * __t45;
            let __t168 = __t137 * __t50;
            let __t199 = __t55 * __t137;
            let __t57 = __t55 - __v15;
            let __t1853 = __t1813 * __t1817;
            let __t1862 = __t1811 * __t1818;
            let __t179 = __t47 * __v2;
            let __t144 = __t52 * __v2;
            let __t140 = __t138 * __t23;
            let __t149 = __t138 * __t22;
            let __t171 = __t168 * __t23;
            let __t175 = __t168 * __t22;
            let __t154 = __t138 * __t24;
            let __t183 = __t168 * __t24;
            let __t201 = __t199 * __t23;
            let __t208 = __t199 * __t22;
            let __t142 = __t140 * __t73;
            let __t151 = __t148 - __t149;
            let __t173 = __t170 - __t171;
            let __t177 = __t175 * __t69;
            let __t78 = __t47 * __t69;
            let __t79 = __t52 * __t73;
            let __t156 = __t154 * __t77;
            let __t158 = __t57 * __v1;
            let __t146 = __t142 + __t144;
            let __t152 = __t151 * __t69;
            let __t174 = __t173 * __t73;
            let __t180 = __t179 - __t177;
            let __t185 = __t183 * __t77;
            let __t187 = __t57 * __v0;
            let __t203 = __t201 * __t73;
            let __t205 = __t52 * __v0;
            let __t210 = __t208 * __t69;
            let __t212 = __t47 * __v1;
            let __t218 = __t199 * __t24;
            let __t80 = __t57 * __t77;
            let __t81 = __t79 + __t78;
            let __t98 = __t52 * __v5;
            let __t100 = __t57 * __v4;
            let __t104 = __t47 * __v5;
            let __t106 = __t57 * __v3;
            let __t153 = __t152 - __t146;
            let __t159 = __t158 - __t156;
            let __t181 = __t180 + __t174;
            let __t189 = __t187 + __t185;
            let __t206 = __t205 - __t203;
            let __t214 = __t212 + __t210;
            let __t220 = __t217 - __t218;
            let __t243 = __t154 * __v4;
            let __t245 = __t140 * __v5;
            let __t252 = __t183 * __v4;
            let __t272 = __t154 * __v3;
            let __t282 = __t183 * __v3;
            let __t284 = __t175 * __v5;
            let __t302 = __t140 * __v3;
            let __t311 = __t175 * __v4;
            let __t82 = __t81 + __t80;
            let __t102 = __t98 - __t100;
            let __t107 = __t106 - __t104;
            let __t109 = __t52 * __v3;
            let __t111 = __t47 * __v4;
            let __t160 = __t159 + __t153;
            let __t191 = __t181 - __t189;
            let __t216 = __t206 - __t214;
            let __t221 = __t220 * __t77;
            let __t247 = __t243 - __t245;
            let __t254 = __t57 - __t252;
            let __t256 = __t173 * __v5;
            let __t264 = __t201 * __v5;
            let __t274 = __t57 - __t272;
            let __t275 = __t151 * __v5;
            let __t286 = __t284 - __t282;
            let __t292 = __t208 * __v5;
            let __t301 = __t151 * __v4;
            let __t304 = __t52 - __t302;
            let __t313 = __t47 - __t311;
            let __t314 = __t173 * __v3;
            let __t321 = __t208 * __v4;
            let __t323 = __t201 * __v3;
            let __t112 = __t111 - __t109;
            let __t222 = __t221 + __t216;
            let __t248 = __t160 * __t102;
            let __t249 = __t247 * __t82;
            let __t257 = __t256 - __t254;
            let __t262 = __t220 * __v4;
            let __t266 = __t52 - __t264;
            let __t277 = __t274 - __t275;
            let __t287 = __t191 * __t107;
            let __t288 = __t286 * __t82;
            let __t291 = __t220 * __v3;
            let __t294 = __t47 - __t292;
            let __t306 = __t301 - __t304;
            let __t316 = __t313 - __t314;
            let __t325 = __t323 - __t321;
            let __t161 = __t160 * __t82;
            let __t192 = __t191 * __t82;
            let __t223 = __t222 * __t82;
            let __t250 = __t249 + __t248;
            let __t258 = __t191 * __t102;
            let __t259 = __t257 * __t82;
            let __t267 = __t266 - __t262;
            let __t278 = __t160 * __t107;
            let __t279 = __t277 * __t82;
            let __t289 = __t288 + __t287;
            let __t296 = __t291 - __t294;
            let __t307 = __t112 * __t160;
            let __t308 = __t306 * __t82;
            let __t317 = __t112 * __t191;
            let __t318 = __t316 * __t82;
            let __t326 = __t222 * __t112;
            let __t327 = __t325 * __t82;
            let __t116 = __t102 * __t82;
            let __t122 = __t107 * __t82;
            let __t128 = __t112 * __t82;
            let __t134 = __t47 * __t87;
            let __t163 = __t161 * __v16;
            let __t166 = __t52 * __t87;
            let __t194 = __t192 * __v16;
            let __t197 = __t57 * __t87;
            let __t225 = __t223 * __v16;
            let __t251 = __t250 * __v16;
            let __t260 = __t259 + __t258;
            let __t268 = __t222 * __t102;
            let __t269 = __t267 * __t82;
            let __t280 = __t279 + __t278;
            let __t290 = __t289 * __v16;
            let __t297 = __t222 * __t107;
            let __t298 = __t296 * __t82;
            let __t309 = __t308 + __t307;
            let __t319 = __t318 + __t317;
            let __t328 = __t327 + __t326;
            let __t118 = __t116 * __v16;
            let __t124 = __t122 * __v16;
            let __t130 = __t128 * __v16;
            let __t165 = __t163 - __t134;
            let __t196 = __t194 - __t166;
            let __t227 = __t225 - __t197;
            let __t261 = __t260 * __v16;
            let __t270 = __t269 + __t268;
            let __t281 = __t280 * __v16;
            let __t299 = __t298 + __t297;
            let __t310 = __t309 * __v16;
            let __t320 = __t319 * __v16;
            let __t329 = __t328 * __v16;
            let __t1832 = __t251 + __t1831;
            let __t1852 = __t290 + __t1851;
            let __t1865 = __t1813 * __t1818;
            let __t271 = __t270 * __v16;
            let __t300 = __t299 * __v16;
            let __t1801 = __t118 + __t1798;
            let __t1802 = __t124 + __t1799;
            let __t1803 = __t130 + __t1800;
            let __t1805 = __t165 + __t1804;
            let __t1807 = __t196 + __t1806;
            let __t1809 = __t227 + __t1808;
            let __t1835 = __t1832 - __t1833;
            let __t1838 = __t261 - __t1836;
            let __t1839 = __t1815 * __t1816;
            let __t1850 = __t281 - __t1848;
            let __t1855 = __t1852 - __t1853;
            let __t1856 = __t1815 * __t1817;
            let __t1864 = __t310 - __t1862;
            let __t1867 = __t320 - __t1865;
            let __t1869 = __t329 + __t1868;
            let __t1870 = __t1815 * __t1818;
            let __t1841 = __t271 - __t1839;
            let __t2118 = __t1835 * __t69;
            let __t2119 = __t1838 * __t73;
            let __t1858 = __t300 - __t1856;
            let __t2123 = __t1850 * __t69;
            let __t2124 = __t1855 * __t73;
            let __t2128 = __t1864 * __t69;
            let __t1872 = __t1869 - __t1870;
            let __t2129 = __t1867 * __t73;
            let __t2133 = __t1802 * __v2;
            let __t2134 = __t1803 * __v1;
            let __t2137 = __t1803 * __v0;
            let __t2138 = __t1801 * __v2;
            let __t2141 = __t1801 * __v1;
            let __t2142 = __t1802 * __v0;
            let __t2145 = __t1807 * __v5;
            let __t2146 = __t1809 * __v4;
            let __t2149 = __t1809 * __v3;
            let __t2150 = __t1805 * __v5;
            let __t2153 = __t1805 * __v4;
            let __t2154 = __t1807 * __v3;
            let __t228 = __t102 * __t102;
            let __t235 = __t107 * __t107;
            let __t240 = __t112 * __t112;
            let __t2120 = __t1841 * __t77;
            let __t2121 = __t2119 + __t2118;
            let __t2125 = __t1858 * __t77;
            let __t2126 = __t2124 + __t2123;
            let __t2130 = __t1872 * __t77;
            let __t2131 = __t2129 + __t2128;
            let __t2136 = __t2133 - __t2134;
            let __t2140 = __t2137 - __t2138;
            let __t2144 = __t2141 - __t2142;
            let __t2148 = __t2145 - __t2146;
            let __t2152 = __t2149 - __t2150;
            let __t2156 = __t2153 - __t2154;
            let __t229 = __t228 * __v16;
            let __t231 = __t107 * __t102;
            let __t233 = __t112 * __t102;
            let __t236 = __t235 * __v16;
            let __t238 = __t112 * __t107;
            let __t241 = __t240 * __v16;
            let __t2122 = __t2121 + __t2120;
            let __t2127 = __t2126 + __t2125;
            let __t2132 = __t2131 + __t2130;
            let __t2157 = __t2148 + __t2136;
            let __t2160 = __t2152 + __t2140;
            let __t2163 = __t2156 + __t2144;
            let __t230 = __t229 + __v7;
            let __t232 = __t231 * __v16;
            let __t234 = __t233 * __v16;
            let __t237 = __t236 + __v8;
            let __t239 = __t238 * __v16;
            let __t242 = __t241 + __v9;
            let __t2159 = __t2157 - __t2122;
            let __t2162 = __t2160 - __t2127;
            let __t2165 = __t2163 - __t2132;
            __ReducedEquations {
                inertia: __Matrix3::new(
                    __t230,
                    __t232,
                    __t234,
                    __t232,
                    __t237,
                    __t239,
                    __t234,
                    __t239,
                    __t242,
                ),
                right_side: __Vector3::new(__t2159, __t2162, __t2165),
                psi_dot: __t1785,
                rank_one: __MaybeRankOne::Some(__RankOneInertia {
                    weight: __v16,
                    vector: __Vector3::new(__t102, __t107, __t112),
                }),
            }
        }
        #[inline]
        fn certification_tape(&self) -> __MaybeTape {
            static __CERTIFICATION_OPS: [__Op; 122] = [
                __Op::Gamma(0),
                __Op::Gamma(1),
                __Op::Gamma(2),
                __Op::PPsi,
                __Op::Param(0),
                __Op::Param(1),
                __Op::Param(2),
                __Op::Param(3),
                __Op::Param(4),
                __Op::Param(5),
                __Op::Param(6),
                __Op::Param(7),
                __Op::Param(8),
                __Op::Param(9),
                __Op::Param(10),
                __Op::Powi(7, 2),
                __Op::Powi(8, 2),
                __Op::Powi(9, 2),
                __Op::Mul(0, 15),
                __Op::Mul(1, 16),
                __Op::Mul(2, 17),
                __Op::Mul(0, 18),
                __Op::Mul(1, 19),
                __Op::Mul(2, 20),
                __Op::Add(21, 22),
                __Op::Add(23, 24),
                __Op::Func(__Func::Sqrt, 25),
                __Op::Neg(10),
                __Op::Recip(26),
                __Op::Mul(18, 28),
                __Op::Add(27, 29),
                __Op::Neg(11),
                __Op::Mul(19, 28),
                __Op::Add(31, 32),
                __Op::Neg(12),
                __Op::Mul(20, 28),
                __Op::Add(34, 35),
                __Op::Mul(13, 14),
                __Op::Mul(30, 37),
                __Op::Neg(38),
                __Op::Powi(28, 2),
                __Op::Mul(29, 40),
                __Op::Mul(15, 28),
                __Op::Mul(18, 41),
                __Op::Neg(43),
                __Op::Add(42, 44),
                __Op::Mul(33, 37),
                __Op::Neg(46),
                __Op::Mul(32, 40),
                __Op::Mul(16, 28),
                __Op::Mul(19, 48),
                __Op::Neg(50),
                __Op::Add(49, 51),
                __Op::Mul(18, 48),
                __Op::Mul(36, 37),
                __Op::Neg(54),
                __Op::Mul(35, 40),
                __Op::Mul(19, 56),
                __Op::Mul(18, 56),
                __Op::Mul(17, 28),
                __Op::Mul(20, 56),
                __Op::Neg(60),
                __Op::Add(59, 61),
                __Op::Mul(0, 4),
                __Op::Mul(1, 5),
                __Op::Mul(2, 6),
                __Op::Mul(0, 63),
                __Op::Mul(1, 64),
                __Op::Mul(2, 65),
                __Op::Add(66, 67),
                __Op::Add(68, 69),
                __Op::Recip(70),
                __Op::Mul(37, 45),
                __Op::Neg(72),
                __Op::Mul(37, 53),
                __Op::Mul(37, 58),
                __Op::Mul(37, 52),
                __Op::Neg(76),
                __Op::Mul(37, 57),
                __Op::Mul(37, 62),
                __Op::Neg(79),
                __Op::Mul(3, 71),
                __Op::Mul(63, 81),
                __Op::Mul(64, 81),
                __Op::Mul(65, 81),
                __Op::Mul(81, 82),
                __Op::Add(39, 85),
                __Op::Mul(81, 83),
                __Op::Add(47, 87),
                __Op::Mul(81, 84),
                __Op::Add(55, 89),
                __Op::Mul(71, 82),
                __Op::Mul(71, 83),
                __Op::Mul(71, 84),
                __Op::Mul(4, 81),
                __Op::Mul(81, 94),
                __Op::Add(73, 95),
                __Op::Mul(82, 91),
                __Op::Const(0xc010000000000000),
                __Op::Mul(98, 97),
                __Op::Add(96, 99),
                __Op::Mul(83, 91),
                __Op::Mul(98, 101),
                __Op::Add(74, 102),
                __Op::Mul(84, 91),
                __Op::Mul(98, 104),
                __Op::Add(75, 105),
                __Op::Mul(5, 81),
                __Op::Mul(81, 107),
                __Op::Add(77, 108),
                __Op::Mul(83, 92),
                __Op::Mul(98, 110),
                __Op::Add(109, 111),
                __Op::Mul(84, 92),
                __Op::Mul(98, 113),
                __Op::Add(78, 114),
                __Op::Mul(6, 81),
                __Op::Mul(81, 116),
                __Op::Add(80, 117),
                __Op::Mul(84, 93),
                __Op::Mul(98, 119),
                __Op::Add(118, 120),
            ];
            static __CERTIFICATION_OUT: [__Output; 9] = [
                __Output {
                    name: "dr_dgamma[0]",
                    slot: 86,
                },
                __Output {
                    name: "dr_dgamma[1]",
                    slot: 88,
                },
                __Output {
                    name: "dr_dgamma[2]",
                    slot: 90,
                },
                __Output {
                    name: "d2r_dgamma2[0][0]",
                    slot: 100,
                },
                __Output {
                    name: "d2r_dgamma2[0][1]",
                    slot: 103,
                },
                __Output {
                    name: "d2r_dgamma2[0][2]",
                    slot: 106,
                },
                __Output {
                    name: "d2r_dgamma2[1][1]",
                    slot: 112,
                },
                __Output {
                    name: "d2r_dgamma2[1][2]",
                    slot: 115,
                },
                __Output {
                    name: "d2r_dgamma2[2][2]",
                    slot: 121,
                },
            ];
            static __CERTIFICATION: __Tape = __Tape::from_static(
                &__CERTIFICATION_OPS,
                &__CERTIFICATION_OUT,
                11,
            );
            __CertificationTape::new(
                    __Tape::clone(&__CERTIFICATION),
                    <[__F64]>::to_vec(
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
                    ),
                )
                .ok()
        }
        #[inline]
        fn routh_tape(&self) -> __MaybeRouthianTape {
            static __ROUTHIAN_OPS: [__Op; 108] = [
                __Op::Omega(0),
                __Op::Omega(1),
                __Op::Omega(2),
                __Op::Gamma(0),
                __Op::Gamma(1),
                __Op::Gamma(2),
                __Op::PPsi,
                __Op::Param(0),
                __Op::Param(1),
                __Op::Param(2),
                __Op::Param(3),
                __Op::Param(4),
                __Op::Param(5),
                __Op::Param(6),
                __Op::Param(7),
                __Op::Param(8),
                __Op::Param(9),
                __Op::Param(10),
                __Op::Powi(10, 2),
                __Op::Powi(11, 2),
                __Op::Powi(12, 2),
                __Op::Mul(3, 18),
                __Op::Mul(4, 19),
                __Op::Mul(5, 20),
                __Op::Mul(3, 21),
                __Op::Mul(4, 22),
                __Op::Mul(5, 23),
                __Op::Add(24, 25),
                __Op::Add(26, 27),
                __Op::Func(__Func::Sqrt, 28),
                __Op::Mul(3, 13),
                __Op::Mul(4, 14),
                __Op::Mul(5, 15),
                __Op::Add(30, 31),
                __Op::Add(32, 33),
                __Op::Neg(34),
                __Op::Add(29, 35),
                __Op::Neg(13),
                __Op::Const(0x3fe0000000000000),
                __Op::Recip(29),
                __Op::Mul(21, 39),
                __Op::Add(37, 40),
                __Op::Neg(14),
                __Op::Mul(22, 39),
                __Op::Add(42, 43),
                __Op::Neg(15),
                __Op::Mul(23, 39),
                __Op::Add(45, 46),
                __Op::Mul(0, 7),
                __Op::Mul(1, 8),
                __Op::Mul(2, 9),
                __Op::Mul(0, 48),
                __Op::Mul(1, 49),
                __Op::Mul(2, 50),
                __Op::Add(51, 52),
                __Op::Add(53, 54),
                __Op::Mul(2, 4),
                __Op::Mul(1, 5),
                __Op::Neg(57),
                __Op::Add(56, 58),
                __Op::Mul(0, 5),
                __Op::Mul(2, 3),
                __Op::Neg(61),
                __Op::Add(60, 62),
                __Op::Mul(1, 3),
                __Op::Mul(0, 4),
                __Op::Neg(65),
                __Op::Add(64, 66),
                __Op::Mul(41, 59),
                __Op::Mul(44, 63),
                __Op::Mul(47, 67),
                __Op::Add(68, 69),
                __Op::Add(70, 71),
                __Op::Powi(72, 2),
                __Op::Mul(16, 73),
                __Op::Add(55, 74),
                __Op::Mul(38, 75),
                __Op::Mul(16, 17),
                __Op::Mul(36, 77),
                __Op::Neg(78),
                __Op::Add(76, 79),
                __Op::Mul(3, 7),
                __Op::Mul(4, 8),
                __Op::Mul(5, 9),
                __Op::Mul(3, 81),
                __Op::Mul(4, 82),
                __Op::Mul(5, 83),
                __Op::Add(84, 85),
                __Op::Add(86, 87),
                __Op::Recip(88),
                __Op::Const(0xbfe0000000000000),
                __Op::Mul(4, 49),
                __Op::Mul(1, 82),
                __Op::Add(91, 92),
                __Op::Mul(3, 48),
                __Op::Mul(0, 81),
                __Op::Add(94, 95),
                __Op::Add(93, 96),
                __Op::Mul(5, 50),
                __Op::Mul(2, 83),
                __Op::Add(98, 99),
                __Op::Add(97, 100),
                __Op::Mul(90, 101),
                __Op::Add(6, 102),
                __Op::Mul(89, 103),
                __Op::Mul(103, 104),
                __Op::Mul(90, 105),
                __Op::Add(80, 106),
            ];
            static __ROUTHIAN_OUT: [__Output; 1] = [
                __Output {
                    name: "routhian",
                    slot: 107,
                },
            ];
            static __ROUTHIAN: __Tape = __Tape::from_static(
                &__ROUTHIAN_OPS,
                &__ROUTHIAN_OUT,
                11,
            );
            __RouthianTape::new(
                    __Tape::clone(&__ROUTHIAN),
                    <[__F64]>::to_vec(
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
                    ),
                )
                .ok()
        }
    }
    #[automatically_derived]
    impl ::routh::__private::DerivedFormulas for DiagonalEllipsoid {
        const LAGRANGIAN: &'static str = "0.5·(ω₃^2·inertia[2] + ω₁^2·inertia[0] + ω₂^2·inertia[1] + mass·((-offset[2] + γ₃·semi_axes[2]^2 / sqrt(γ₃^2·semi_axes[2]^2 + γ₁^2·semi_axes[0]^2 + γ₂^2·semi_axes[1]^2))·(ω₂·γ₁ - ω₁·γ₂) + (-offset[0] + γ₁·semi_axes[0]^2 / sqrt(γ₃^2·semi_axes[2]^2 + γ₁^2·semi_axes[0]^2 + γ₂^2·semi_axes[1]^2))·(ω₃·γ₂ - ω₂·γ₃) + (-offset[1] + γ₂·semi_axes[1]^2 / sqrt(γ₃^2·semi_axes[2]^2 + γ₁^2·semi_axes[0]^2 + γ₂^2·semi_axes[1]^2))·(ω₁·γ₃ - ω₃·γ₁))^2) - (sqrt(γ₃^2·semi_axes[2]^2 + γ₁^2·semi_axes[0]^2 + γ₂^2·semi_axes[1]^2) - (γ₃·offset[2] + γ₁·offset[0] + γ₂·offset[1]))·mass·g";
        const AMENDED_POTENTIAL: &'static str = "(sqrt(γ₃^2·semi_axes[2]^2 + γ₁^2·semi_axes[0]^2 + γ₂^2·semi_axes[1]^2) - (γ₃·offset[2] + γ₁·offset[0] + γ₂·offset[1]))·mass·g + 0.5·p_ψ^2 / (γ₃^2·inertia[2] + γ₁^2·inertia[0] + γ₂^2·inertia[1])";
        const PSI_DOT_AT_REST: &'static str = "p_ψ / (γ₃^2·inertia[2] + γ₁^2·inertia[0] + γ₂^2·inertia[1])";
        fn latex(&self) -> ::routh::__private::LatexFormulas {
            static __LATEX: ::routh::__private::DerivedLatex = ::routh::__private::DerivedLatex::new(
                "# [lagrangian (let d = diag (semi_axes . component_mul (semi_axes)) , let c3 = gamma . dot (d * gamma) . sqrt () - offset . dot (gamma) , let n = grad (c3 , gamma) , kinetic = 0.5 * (omega . dot (diag (inertia) * omega) + mass * n . dot (gamma . cross (omega)) . powi (2)) , potential = mass * g * c3 ,)] pub struct DiagonalEllipsoid { pub inertia : Vector3 < f64 > , pub semi_axes : Vector3 < f64 > , pub offset : Vector3 < f64 > , pub mass : f64 , pub g : f64 , }",
            );
            __LATEX.get()
        }
    }
};
