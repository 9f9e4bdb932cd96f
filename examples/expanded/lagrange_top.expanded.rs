/// The Lagrange top: a heavy symmetric top about a fixed point on its axis.
#[derive(Lagrangian)]
#[lagrangian(
    kinetic = 0.5*(a1*(omega.x*omega.x+omega.y*omega.y)+c*omega.z*omega.z),
    potential = mgl*gamma.z,
)]
pub struct LagrangeTop {
    /// Equatorial moment of inertia A₁ about the fixed point.
    pub a1: f64,
    /// Axial moment of inertia C.
    pub c: f64,
    /// m g l: weight times the distance of the centre of mass from the fixed point.
    pub mgl: f64,
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
    #[automatically_derived]
    impl ::routh::__private::Lagrangian for LagrangeTop {
        #[inline]
        fn lagrangian(
            &self,
            __omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
        ) -> ::routh::__private::f64 {
            let __v0: ::routh::__private::f64 = __omega[0usize];
            let __v1: ::routh::__private::f64 = __omega[1usize];
            let __v2: ::routh::__private::f64 = __omega[2usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __v9: ::routh::__private::f64 = self.mgl;
            let __t11: ::routh::__private::f64 = __v0 * __v0;
            let __t12: ::routh::__private::f64 = __v1 * __v1;
            let __t13: ::routh::__private::f64 = __t11 + __t12;
            let __t14: ::routh::__private::f64 = __v7 * __t13;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t16: ::routh::__private::f64 = __v2 * __t15;
            let __t17: ::routh::__private::f64 = __t14 + __t16;
            let __t18: ::routh::__private::f64 = 0.5f64 * __t17;
            let __t19: ::routh::__private::f64 = __v5 * __v9;
            let __t22: ::routh::__private::f64 = __t18 - __t19;
            __t22
        }
        #[inline]
        fn dl_domega(
            &self,
            __omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
        ) -> ::routh::__private::Vector3<::routh::__private::f64> {
            let __v0: ::routh::__private::f64 = __omega[0usize];
            let __v1: ::routh::__private::f64 = __omega[1usize];
            let __v2: ::routh::__private::f64 = __omega[2usize];
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t26: ::routh::__private::f64 = __v0 * __v7;
            let __t29: ::routh::__private::f64 = __v1 * __v7;
            ::routh::__private::Vector3::new(__t26, __t29, __t15)
        }
        #[inline]
        fn dl_dgamma(
            &self,
            __omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
        ) -> ::routh::__private::Vector3<::routh::__private::f64> {
            let __v9: ::routh::__private::f64 = self.mgl;
            let __t32: ::routh::__private::f64 = -__v9;
            ::routh::__private::Vector3::new(0f64, 0f64, __t32)
        }
        #[inline]
        fn d2l_domega2(
            &self,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
        ) -> ::routh::__private::Matrix3<::routh::__private::f64> {
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            ::routh::__private::Matrix3::new(
                __v7,
                0f64,
                0f64,
                0f64,
                __v7,
                0f64,
                0f64,
                0f64,
                __v8,
            )
        }
        #[inline]
        fn d2l_domega_dgamma(
            &self,
            __omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
        ) -> ::routh::__private::Matrix3<::routh::__private::f64> {
            ::routh::__private::Matrix3::new(
                0f64,
                0f64,
                0f64,
                0f64,
                0f64,
                0f64,
                0f64,
                0f64,
                0f64,
            )
        }
        #[inline]
        fn energy(
            &self,
            __omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
        ) -> ::routh::__private::f64 {
            let __v0: ::routh::__private::f64 = __omega[0usize];
            let __v1: ::routh::__private::f64 = __omega[1usize];
            let __v2: ::routh::__private::f64 = __omega[2usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __v9: ::routh::__private::f64 = self.mgl;
            let __t11: ::routh::__private::f64 = __v0 * __v0;
            let __t12: ::routh::__private::f64 = __v1 * __v1;
            let __t13: ::routh::__private::f64 = __t11 + __t12;
            let __t14: ::routh::__private::f64 = __v7 * __t13;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t16: ::routh::__private::f64 = __v2 * __t15;
            let __t17: ::routh::__private::f64 = __t14 + __t16;
            let __t18: ::routh::__private::f64 = 0.5f64 * __t17;
            let __t19: ::routh::__private::f64 = __v5 * __v9;
            let __t22: ::routh::__private::f64 = __t18 - __t19;
            let __t26: ::routh::__private::f64 = __v0 * __v7;
            let __t29: ::routh::__private::f64 = __v1 * __v7;
            let __t33: ::routh::__private::f64 = __v0 * __t26;
            let __t34: ::routh::__private::f64 = __v1 * __t29;
            let __t35: ::routh::__private::f64 = __t33 + __t34;
            let __t36: ::routh::__private::f64 = __t16 + __t35;
            let __t38: ::routh::__private::f64 = __t36 - __t22;
            __t38
        }
        #[inline]
        fn cyclic_momentum(
            &self,
            __omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
        ) -> ::routh::__private::f64 {
            let __v0: ::routh::__private::f64 = __omega[0usize];
            let __v1: ::routh::__private::f64 = __omega[1usize];
            let __v2: ::routh::__private::f64 = __omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t26: ::routh::__private::f64 = __v0 * __v7;
            let __t29: ::routh::__private::f64 = __v1 * __v7;
            let __t39: ::routh::__private::f64 = __v3 * __t26;
            let __t40: ::routh::__private::f64 = __v4 * __t29;
            let __t41: ::routh::__private::f64 = __v5 * __t15;
            let __t42: ::routh::__private::f64 = __t39 + __t40;
            let __t43: ::routh::__private::f64 = __t41 + __t42;
            __t43
        }
    }
    #[automatically_derived]
    impl ::routh::__private::Routhian for LagrangeTop {
        #[inline]
        fn psi_dot(
            &self,
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::f64 {
            let __v0: ::routh::__private::f64 = __big_omega[0usize];
            let __v1: ::routh::__private::f64 = __big_omega[1usize];
            let __v2: ::routh::__private::f64 = __big_omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t26: ::routh::__private::f64 = __v0 * __v7;
            let __t29: ::routh::__private::f64 = __v1 * __v7;
            let __t39: ::routh::__private::f64 = __v3 * __t26;
            let __t40: ::routh::__private::f64 = __v4 * __t29;
            let __t41: ::routh::__private::f64 = __v5 * __t15;
            let __t42: ::routh::__private::f64 = __t39 + __t40;
            let __t43: ::routh::__private::f64 = __t41 + __t42;
            let __t44: ::routh::__private::f64 = __v3 * __v3;
            let __t45: ::routh::__private::f64 = __v4 * __v4;
            let __t46: ::routh::__private::f64 = __t44 + __t45;
            let __t47: ::routh::__private::f64 = __v7 * __t46;
            let __t48: ::routh::__private::f64 = __v5 * __v8;
            let __t49: ::routh::__private::f64 = __v5 * __t48;
            let __t50: ::routh::__private::f64 = __t47 + __t49;
            let __t53: ::routh::__private::f64 = __v6 - __t43;
            let __t55: ::routh::__private::f64 = __t53 / __t50;
            __t55
        }
        #[inline]
        fn routhian(
            &self,
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::f64 {
            let __v0: ::routh::__private::f64 = __big_omega[0usize];
            let __v1: ::routh::__private::f64 = __big_omega[1usize];
            let __v2: ::routh::__private::f64 = __big_omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __v9: ::routh::__private::f64 = self.mgl;
            let __t11: ::routh::__private::f64 = __v0 * __v0;
            let __t12: ::routh::__private::f64 = __v1 * __v1;
            let __t13: ::routh::__private::f64 = __t11 + __t12;
            let __t14: ::routh::__private::f64 = __v7 * __t13;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t16: ::routh::__private::f64 = __v2 * __t15;
            let __t17: ::routh::__private::f64 = __t14 + __t16;
            let __t18: ::routh::__private::f64 = 0.5f64 * __t17;
            let __t19: ::routh::__private::f64 = __v5 * __v9;
            let __t22: ::routh::__private::f64 = __t18 - __t19;
            let __t26: ::routh::__private::f64 = __v0 * __v7;
            let __t29: ::routh::__private::f64 = __v1 * __v7;
            let __t39: ::routh::__private::f64 = __v3 * __t26;
            let __t40: ::routh::__private::f64 = __v4 * __t29;
            let __t41: ::routh::__private::f64 = __v5 * __t15;
            let __t42: ::routh::__private::f64 = __t39 + __t40;
            let __t43: ::routh::__private::f64 = __t41 + __t42;
            let __t44: ::routh::__private::f64 = __v3 * __v3;
            let __t45: ::routh::__private::f64 = __v4 * __v4;
            let __t46: ::routh::__private::f64 = __t44 + __t45;
            let __t47: ::routh::__private::f64 = __v7 * __t46;
            let __t48: ::routh::__private::f64 = __v5 * __v8;
            let __t49: ::routh::__private::f64 = __v5 * __t48;
            let __t50: ::routh::__private::f64 = __t47 + __t49;
            let __t53: ::routh::__private::f64 = __v6 - __t43;
            let __t55: ::routh::__private::f64 = __t53 / __t50;
            let __t57: ::routh::__private::f64 = __t53 * __t55;
            let __t60: ::routh::__private::f64 = (-0.5f64) * __t57;
            let __t61: ::routh::__private::f64 = __t22 + __t60;
            __t61
        }
        #[inline]
        fn dr_domega(
            &self,
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::Vector3<::routh::__private::f64> {
            let __v0: ::routh::__private::f64 = __big_omega[0usize];
            let __v1: ::routh::__private::f64 = __big_omega[1usize];
            let __v2: ::routh::__private::f64 = __big_omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t26: ::routh::__private::f64 = __v0 * __v7;
            let __t29: ::routh::__private::f64 = __v1 * __v7;
            let __t39: ::routh::__private::f64 = __v3 * __t26;
            let __t40: ::routh::__private::f64 = __v4 * __t29;
            let __t41: ::routh::__private::f64 = __v5 * __t15;
            let __t42: ::routh::__private::f64 = __t39 + __t40;
            let __t43: ::routh::__private::f64 = __t41 + __t42;
            let __t44: ::routh::__private::f64 = __v3 * __v3;
            let __t45: ::routh::__private::f64 = __v4 * __v4;
            let __t46: ::routh::__private::f64 = __t44 + __t45;
            let __t47: ::routh::__private::f64 = __v7 * __t46;
            let __t48: ::routh::__private::f64 = __v5 * __v8;
            let __t49: ::routh::__private::f64 = __v5 * __t48;
            let __t50: ::routh::__private::f64 = __t47 + __t49;
            let __t53: ::routh::__private::f64 = __v6 - __t43;
            let __t55: ::routh::__private::f64 = __t53 / __t50;
            let __t62: ::routh::__private::f64 = __v3 * __t55;
            let __t63: ::routh::__private::f64 = __v0 + __t62;
            let __t64: ::routh::__private::f64 = __v4 * __t55;
            let __t65: ::routh::__private::f64 = __v1 + __t64;
            let __t66: ::routh::__private::f64 = __v5 * __t55;
            let __t67: ::routh::__private::f64 = __v2 + __t66;
            let __t72: ::routh::__private::f64 = __v8 * __t67;
            let __t78: ::routh::__private::f64 = __v7 * __t63;
            let __t81: ::routh::__private::f64 = __v7 * __t65;
            ::routh::__private::Vector3::new(__t78, __t81, __t72)
        }
        #[inline]
        fn dr_dgamma(
            &self,
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::Vector3<::routh::__private::f64> {
            let __v0: ::routh::__private::f64 = __big_omega[0usize];
            let __v1: ::routh::__private::f64 = __big_omega[1usize];
            let __v2: ::routh::__private::f64 = __big_omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __v9: ::routh::__private::f64 = self.mgl;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t26: ::routh::__private::f64 = __v0 * __v7;
            let __t29: ::routh::__private::f64 = __v1 * __v7;
            let __t39: ::routh::__private::f64 = __v3 * __t26;
            let __t40: ::routh::__private::f64 = __v4 * __t29;
            let __t41: ::routh::__private::f64 = __v5 * __t15;
            let __t42: ::routh::__private::f64 = __t39 + __t40;
            let __t43: ::routh::__private::f64 = __t41 + __t42;
            let __t44: ::routh::__private::f64 = __v3 * __v3;
            let __t45: ::routh::__private::f64 = __v4 * __v4;
            let __t46: ::routh::__private::f64 = __t44 + __t45;
            let __t47: ::routh::__private::f64 = __v7 * __t46;
            let __t48: ::routh::__private::f64 = __v5 * __v8;
            let __t49: ::routh::__private::f64 = __v5 * __t48;
            let __t50: ::routh::__private::f64 = __t47 + __t49;
            let __t53: ::routh::__private::f64 = __v6 - __t43;
            let __t55: ::routh::__private::f64 = __t53 / __t50;
            let __t62: ::routh::__private::f64 = __v3 * __t55;
            let __t63: ::routh::__private::f64 = __v0 + __t62;
            let __t64: ::routh::__private::f64 = __v4 * __t55;
            let __t65: ::routh::__private::f64 = __v1 + __t64;
            let __t66: ::routh::__private::f64 = __v5 * __t55;
            let __t67: ::routh::__private::f64 = __v2 + __t66;
            let __t72: ::routh::__private::f64 = __v8 * __t67;
            let __t78: ::routh::__private::f64 = __v7 * __t63;
            let __t81: ::routh::__private::f64 = __v7 * __t65;
            let __t84: ::routh::__private::f64 = __t55 * __t78;
            let __t85: ::routh::__private::f64 = __t55 * __t81;
            let __t86: ::routh::__private::f64 = __t55 * __t72;
            let __t87: ::routh::__private::f64 = __t86 - __v9;
            ::routh::__private::Vector3::new(__t84, __t85, __t87)
        }
        #[inline]
        fn dr_dp(
            &self,
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::f64 {
            let __v0: ::routh::__private::f64 = __big_omega[0usize];
            let __v1: ::routh::__private::f64 = __big_omega[1usize];
            let __v2: ::routh::__private::f64 = __big_omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t26: ::routh::__private::f64 = __v0 * __v7;
            let __t29: ::routh::__private::f64 = __v1 * __v7;
            let __t39: ::routh::__private::f64 = __v3 * __t26;
            let __t40: ::routh::__private::f64 = __v4 * __t29;
            let __t41: ::routh::__private::f64 = __v5 * __t15;
            let __t42: ::routh::__private::f64 = __t39 + __t40;
            let __t43: ::routh::__private::f64 = __t41 + __t42;
            let __t44: ::routh::__private::f64 = __v3 * __v3;
            let __t45: ::routh::__private::f64 = __v4 * __v4;
            let __t46: ::routh::__private::f64 = __t44 + __t45;
            let __t47: ::routh::__private::f64 = __v7 * __t46;
            let __t48: ::routh::__private::f64 = __v5 * __v8;
            let __t49: ::routh::__private::f64 = __v5 * __t48;
            let __t50: ::routh::__private::f64 = __t47 + __t49;
            let __t53: ::routh::__private::f64 = __v6 - __t43;
            let __t55: ::routh::__private::f64 = __t53 / __t50;
            let __t88: ::routh::__private::f64 = -__t55;
            __t88
        }
        #[inline]
        fn d2r_domega2(
            &self,
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::Matrix3<::routh::__private::f64> {
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __t44: ::routh::__private::f64 = __v3 * __v3;
            let __t45: ::routh::__private::f64 = __v4 * __v4;
            let __t46: ::routh::__private::f64 = __t44 + __t45;
            let __t47: ::routh::__private::f64 = __v7 * __t46;
            let __t48: ::routh::__private::f64 = __v5 * __v8;
            let __t49: ::routh::__private::f64 = __v5 * __t48;
            let __t50: ::routh::__private::f64 = __t47 + __t49;
            let __t54: ::routh::__private::f64 = 1.0f64 / __t50;
            let __t89: ::routh::__private::f64 = __v3 * __v7;
            let __t91: ::routh::__private::f64 = __t54 * __t89;
            let __t93: ::routh::__private::f64 = __v3 * __t91;
            let __t95: ::routh::__private::f64 = 1f64 - __t93;
            let __t96: ::routh::__private::f64 = __v7 * __t95;
            let __t97: ::routh::__private::f64 = __v4 * __v7;
            let __t99: ::routh::__private::f64 = __t54 * __t97;
            let __t101: ::routh::__private::f64 = __v3 * __t99;
            let __t103: ::routh::__private::f64 = __v7 * __t101;
            let __t104: ::routh::__private::f64 = -__t103;
            let __t106: ::routh::__private::f64 = __t48 * __t54;
            let __t108: ::routh::__private::f64 = __v3 * __t106;
            let __t110: ::routh::__private::f64 = __v7 * __t108;
            let __t111: ::routh::__private::f64 = -__t110;
            let __t112: ::routh::__private::f64 = __v4 * __t99;
            let __t114: ::routh::__private::f64 = 1f64 - __t112;
            let __t115: ::routh::__private::f64 = __v7 * __t114;
            let __t116: ::routh::__private::f64 = __v4 * __t106;
            let __t118: ::routh::__private::f64 = __v7 * __t116;
            let __t119: ::routh::__private::f64 = -__t118;
            let __t120: ::routh::__private::f64 = __v5 * __t106;
            let __t122: ::routh::__private::f64 = 1f64 - __t120;
            let __t123: ::routh::__private::f64 = __v8 * __t122;
            ::routh::__private::Matrix3::new(
                __t96,
                __t104,
                __t111,
                __t104,
                __t115,
                __t119,
                __t111,
                __t119,
                __t123,
            )
        }
        #[inline]
        fn d2r_domega_dgamma(
            &self,
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::Matrix3<::routh::__private::f64> {
            let __v0: ::routh::__private::f64 = __big_omega[0usize];
            let __v1: ::routh::__private::f64 = __big_omega[1usize];
            let __v2: ::routh::__private::f64 = __big_omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t26: ::routh::__private::f64 = __v0 * __v7;
            let __t29: ::routh::__private::f64 = __v1 * __v7;
            let __t39: ::routh::__private::f64 = __v3 * __t26;
            let __t40: ::routh::__private::f64 = __v4 * __t29;
            let __t41: ::routh::__private::f64 = __v5 * __t15;
            let __t42: ::routh::__private::f64 = __t39 + __t40;
            let __t43: ::routh::__private::f64 = __t41 + __t42;
            let __t44: ::routh::__private::f64 = __v3 * __v3;
            let __t45: ::routh::__private::f64 = __v4 * __v4;
            let __t46: ::routh::__private::f64 = __t44 + __t45;
            let __t47: ::routh::__private::f64 = __v7 * __t46;
            let __t48: ::routh::__private::f64 = __v5 * __v8;
            let __t49: ::routh::__private::f64 = __v5 * __t48;
            let __t50: ::routh::__private::f64 = __t47 + __t49;
            let __t53: ::routh::__private::f64 = __v6 - __t43;
            let __t54: ::routh::__private::f64 = 1.0f64 / __t50;
            let __t55: ::routh::__private::f64 = __t53 * __t54;
            let __t89: ::routh::__private::f64 = __v3 * __v7;
            let __t97: ::routh::__private::f64 = __v4 * __v7;
            let __t126: ::routh::__private::f64 = __t50 * __t50;
            let __t127: ::routh::__private::f64 = 1.0f64 / __t126;
            let __t128: ::routh::__private::f64 = __t89 * __t127;
            let __t133: ::routh::__private::f64 = __t26 * __t54;
            let __t135: ::routh::__private::f64 = __t53 * __t128;
            let __t136: ::routh::__private::f64 = (-2f64) * __t135;
            let __t137: ::routh::__private::f64 = __t136 - __t133;
            let __t138: ::routh::__private::f64 = __v3 * __t137;
            let __t139: ::routh::__private::f64 = __t55 + __t138;
            let __t140: ::routh::__private::f64 = __v7 * __t139;
            let __t143: ::routh::__private::f64 = __t97 * __t127;
            let __t147: ::routh::__private::f64 = __t29 * __t54;
            let __t149: ::routh::__private::f64 = __t53 * __t143;
            let __t150: ::routh::__private::f64 = (-2f64) * __t149;
            let __t151: ::routh::__private::f64 = __t150 - __t147;
            let __t152: ::routh::__private::f64 = __v3 * __t151;
            let __t153: ::routh::__private::f64 = __v7 * __t152;
            let __t155: ::routh::__private::f64 = __t48 * __t127;
            let __t159: ::routh::__private::f64 = __t15 * __t54;
            let __t161: ::routh::__private::f64 = __t53 * __t155;
            let __t162: ::routh::__private::f64 = (-2f64) * __t161;
            let __t163: ::routh::__private::f64 = __t162 - __t159;
            let __t164: ::routh::__private::f64 = __v3 * __t163;
            let __t165: ::routh::__private::f64 = __v7 * __t164;
            let __t166: ::routh::__private::f64 = __v4 * __t137;
            let __t167: ::routh::__private::f64 = __v7 * __t166;
            let __t168: ::routh::__private::f64 = __v4 * __t151;
            let __t169: ::routh::__private::f64 = __t55 + __t168;
            let __t170: ::routh::__private::f64 = __v7 * __t169;
            let __t171: ::routh::__private::f64 = __v4 * __t163;
            let __t172: ::routh::__private::f64 = __v7 * __t171;
            let __t173: ::routh::__private::f64 = __v5 * __t137;
            let __t174: ::routh::__private::f64 = __v8 * __t173;
            let __t175: ::routh::__private::f64 = __v5 * __t151;
            let __t176: ::routh::__private::f64 = __v8 * __t175;
            let __t177: ::routh::__private::f64 = __v5 * __t163;
            let __t178: ::routh::__private::f64 = __t55 + __t177;
            let __t179: ::routh::__private::f64 = __v8 * __t178;
            ::routh::__private::Matrix3::new(
                __t140,
                __t153,
                __t165,
                __t167,
                __t170,
                __t172,
                __t174,
                __t176,
                __t179,
            )
        }
        #[inline]
        fn d2r_dgamma2(
            &self,
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::Matrix3<::routh::__private::f64> {
            let __v0: ::routh::__private::f64 = __big_omega[0usize];
            let __v1: ::routh::__private::f64 = __big_omega[1usize];
            let __v2: ::routh::__private::f64 = __big_omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t26: ::routh::__private::f64 = __v0 * __v7;
            let __t29: ::routh::__private::f64 = __v1 * __v7;
            let __t39: ::routh::__private::f64 = __v3 * __t26;
            let __t40: ::routh::__private::f64 = __v4 * __t29;
            let __t41: ::routh::__private::f64 = __v5 * __t15;
            let __t42: ::routh::__private::f64 = __t39 + __t40;
            let __t43: ::routh::__private::f64 = __t41 + __t42;
            let __t44: ::routh::__private::f64 = __v3 * __v3;
            let __t45: ::routh::__private::f64 = __v4 * __v4;
            let __t46: ::routh::__private::f64 = __t44 + __t45;
            let __t47: ::routh::__private::f64 = __v7 * __t46;
            let __t48: ::routh::__private::f64 = __v5 * __v8;
            let __t49: ::routh::__private::f64 = __v5 * __t48;
            let __t50: ::routh::__private::f64 = __t47 + __t49;
            let __t53: ::routh::__private::f64 = __v6 - __t43;
            let __t54: ::routh::__private::f64 = 1.0f64 / __t50;
            let __t55: ::routh::__private::f64 = __t53 * __t54;
            let __t62: ::routh::__private::f64 = __v3 * __t55;
            let __t63: ::routh::__private::f64 = __v0 + __t62;
            let __t64: ::routh::__private::f64 = __v4 * __t55;
            let __t65: ::routh::__private::f64 = __v1 + __t64;
            let __t66: ::routh::__private::f64 = __v5 * __t55;
            let __t67: ::routh::__private::f64 = __v2 + __t66;
            let __t72: ::routh::__private::f64 = __v8 * __t67;
            let __t78: ::routh::__private::f64 = __v7 * __t63;
            let __t81: ::routh::__private::f64 = __v7 * __t65;
            let __t89: ::routh::__private::f64 = __v3 * __v7;
            let __t97: ::routh::__private::f64 = __v4 * __v7;
            let __t126: ::routh::__private::f64 = __t50 * __t50;
            let __t127: ::routh::__private::f64 = 1.0f64 / __t126;
            let __t128: ::routh::__private::f64 = __t89 * __t127;
            let __t133: ::routh::__private::f64 = __t26 * __t54;
            let __t135: ::routh::__private::f64 = __t53 * __t128;
            let __t136: ::routh::__private::f64 = (-2f64) * __t135;
            let __t137: ::routh::__private::f64 = __t136 - __t133;
            let __t138: ::routh::__private::f64 = __v3 * __t137;
            let __t139: ::routh::__private::f64 = __t55 + __t138;
            let __t140: ::routh::__private::f64 = __v7 * __t139;
            let __t143: ::routh::__private::f64 = __t97 * __t127;
            let __t147: ::routh::__private::f64 = __t29 * __t54;
            let __t149: ::routh::__private::f64 = __t53 * __t143;
            let __t150: ::routh::__private::f64 = (-2f64) * __t149;
            let __t151: ::routh::__private::f64 = __t150 - __t147;
            let __t152: ::routh::__private::f64 = __v3 * __t151;
            let __t153: ::routh::__private::f64 = __v7 * __t152;
            let __t155: ::routh::__private::f64 = __t48 * __t127;
            let __t159: ::routh::__private::f64 = __t15 * __t54;
            let __t161: ::routh::__private::f64 = __t53 * __t155;
            let __t162: ::routh::__private::f64 = (-2f64) * __t161;
            let __t163: ::routh::__private::f64 = __t162 - __t159;
            let __t164: ::routh::__private::f64 = __v3 * __t163;
            let __t165: ::routh::__private::f64 = __v7 * __t164;
            let __t168: ::routh::__private::f64 = __v4 * __t151;
            let __t169: ::routh::__private::f64 = __t55 + __t168;
            let __t170: ::routh::__private::f64 = __v7 * __t169;
            let __t171: ::routh::__private::f64 = __v4 * __t163;
            let __t172: ::routh::__private::f64 = __v7 * __t171;
            let __t177: ::routh::__private::f64 = __v5 * __t163;
            let __t178: ::routh::__private::f64 = __t55 + __t177;
            let __t179: ::routh::__private::f64 = __v8 * __t178;
            let __t180: ::routh::__private::f64 = __t78 * __t137;
            let __t181: ::routh::__private::f64 = __t55 * __t140;
            let __t182: ::routh::__private::f64 = __t180 + __t181;
            let __t183: ::routh::__private::f64 = __t78 * __t151;
            let __t184: ::routh::__private::f64 = __t55 * __t153;
            let __t185: ::routh::__private::f64 = __t183 + __t184;
            let __t186: ::routh::__private::f64 = __t78 * __t163;
            let __t187: ::routh::__private::f64 = __t55 * __t165;
            let __t188: ::routh::__private::f64 = __t186 + __t187;
            let __t189: ::routh::__private::f64 = __t81 * __t151;
            let __t190: ::routh::__private::f64 = __t55 * __t170;
            let __t191: ::routh::__private::f64 = __t189 + __t190;
            let __t192: ::routh::__private::f64 = __t81 * __t163;
            let __t193: ::routh::__private::f64 = __t55 * __t172;
            let __t194: ::routh::__private::f64 = __t192 + __t193;
            let __t195: ::routh::__private::f64 = __t72 * __t163;
            let __t196: ::routh::__private::f64 = __t55 * __t179;
            let __t197: ::routh::__private::f64 = __t195 + __t196;
            ::routh::__private::Matrix3::new(
                __t182,
                __t185,
                __t188,
                __t185,
                __t191,
                __t194,
                __t188,
                __t194,
                __t197,
            )
        }
        #[inline]
        fn amended_potential(
            &self,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::f64 {
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __v9: ::routh::__private::f64 = self.mgl;
            let __t19: ::routh::__private::f64 = __v5 * __v9;
            let __t44: ::routh::__private::f64 = __v3 * __v3;
            let __t45: ::routh::__private::f64 = __v4 * __v4;
            let __t46: ::routh::__private::f64 = __t44 + __t45;
            let __t47: ::routh::__private::f64 = __v7 * __t46;
            let __t48: ::routh::__private::f64 = __v5 * __v8;
            let __t49: ::routh::__private::f64 = __v5 * __t48;
            let __t50: ::routh::__private::f64 = __t47 + __t49;
            let __t198: ::routh::__private::f64 = __v6 / __t50;
            let __t200: ::routh::__private::f64 = __v6 * __t198;
            let __t202: ::routh::__private::f64 = (-0.5f64) * __t200;
            let __t203: ::routh::__private::f64 = __t202 - __t19;
            let __t297: ::routh::__private::f64 = -__t203;
            __t297
        }
        #[inline]
        fn bundle(
            &self,
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::RouthBundle {
            let __v0: ::routh::__private::f64 = __big_omega[0usize];
            let __v1: ::routh::__private::f64 = __big_omega[1usize];
            let __v2: ::routh::__private::f64 = __big_omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __v9: ::routh::__private::f64 = self.mgl;
            let __t11: ::routh::__private::f64 = __v0 * __v0;
            let __t12: ::routh::__private::f64 = __v1 * __v1;
            let __t13: ::routh::__private::f64 = __t11 + __t12;
            let __t14: ::routh::__private::f64 = __v7 * __t13;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t16: ::routh::__private::f64 = __v2 * __t15;
            let __t17: ::routh::__private::f64 = __t14 + __t16;
            let __t18: ::routh::__private::f64 = 0.5f64 * __t17;
            let __t19: ::routh::__private::f64 = __v5 * __v9;
            let __t22: ::routh::__private::f64 = __t18 - __t19;
            let __t26: ::routh::__private::f64 = __v0 * __v7;
            let __t29: ::routh::__private::f64 = __v1 * __v7;
            let __t39: ::routh::__private::f64 = __v3 * __t26;
            let __t40: ::routh::__private::f64 = __v4 * __t29;
            let __t41: ::routh::__private::f64 = __v5 * __t15;
            let __t42: ::routh::__private::f64 = __t39 + __t40;
            let __t43: ::routh::__private::f64 = __t41 + __t42;
            let __t44: ::routh::__private::f64 = __v3 * __v3;
            let __t45: ::routh::__private::f64 = __v4 * __v4;
            let __t46: ::routh::__private::f64 = __t44 + __t45;
            let __t47: ::routh::__private::f64 = __v7 * __t46;
            let __t48: ::routh::__private::f64 = __v5 * __v8;
            let __t49: ::routh::__private::f64 = __v5 * __t48;
            let __t50: ::routh::__private::f64 = __t47 + __t49;
            let __t53: ::routh::__private::f64 = __v6 - __t43;
            let __t54: ::routh::__private::f64 = 1.0f64 / __t50;
            let __t55: ::routh::__private::f64 = __t53 * __t54;
            let __t57: ::routh::__private::f64 = __t53 * __t55;
            let __t60: ::routh::__private::f64 = (-0.5f64) * __t57;
            let __t61: ::routh::__private::f64 = __t22 + __t60;
            let __t62: ::routh::__private::f64 = __v3 * __t55;
            let __t63: ::routh::__private::f64 = __v0 + __t62;
            let __t64: ::routh::__private::f64 = __v4 * __t55;
            let __t65: ::routh::__private::f64 = __v1 + __t64;
            let __t66: ::routh::__private::f64 = __v5 * __t55;
            let __t67: ::routh::__private::f64 = __v2 + __t66;
            let __t72: ::routh::__private::f64 = __v8 * __t67;
            let __t78: ::routh::__private::f64 = __v7 * __t63;
            let __t81: ::routh::__private::f64 = __v7 * __t65;
            let __t84: ::routh::__private::f64 = __t55 * __t78;
            let __t85: ::routh::__private::f64 = __t55 * __t81;
            let __t86: ::routh::__private::f64 = __t55 * __t72;
            let __t87: ::routh::__private::f64 = __t86 - __v9;
            let __t88: ::routh::__private::f64 = -__t55;
            let __t89: ::routh::__private::f64 = __v3 * __v7;
            let __t91: ::routh::__private::f64 = __t54 * __t89;
            let __t93: ::routh::__private::f64 = __v3 * __t91;
            let __t95: ::routh::__private::f64 = 1f64 - __t93;
            let __t96: ::routh::__private::f64 = __v7 * __t95;
            let __t97: ::routh::__private::f64 = __v4 * __v7;
            let __t99: ::routh::__private::f64 = __t54 * __t97;
            let __t101: ::routh::__private::f64 = __v3 * __t99;
            let __t103: ::routh::__private::f64 = __v7 * __t101;
            let __t104: ::routh::__private::f64 = -__t103;
            let __t106: ::routh::__private::f64 = __t48 * __t54;
            let __t108: ::routh::__private::f64 = __v3 * __t106;
            let __t110: ::routh::__private::f64 = __v7 * __t108;
            let __t111: ::routh::__private::f64 = -__t110;
            let __t112: ::routh::__private::f64 = __v4 * __t99;
            let __t114: ::routh::__private::f64 = 1f64 - __t112;
            let __t115: ::routh::__private::f64 = __v7 * __t114;
            let __t116: ::routh::__private::f64 = __v4 * __t106;
            let __t118: ::routh::__private::f64 = __v7 * __t116;
            let __t119: ::routh::__private::f64 = -__t118;
            let __t120: ::routh::__private::f64 = __v5 * __t106;
            let __t122: ::routh::__private::f64 = 1f64 - __t120;
            let __t123: ::routh::__private::f64 = __v8 * __t122;
            let __t126: ::routh::__private::f64 = __t50 * __t50;
            let __t127: ::routh::__private::f64 = 1.0f64 / __t126;
            let __t128: ::routh::__private::f64 = __t89 * __t127;
            let __t133: ::routh::__private::f64 = __t26 * __t54;
            let __t135: ::routh::__private::f64 = __t53 * __t128;
            let __t136: ::routh::__private::f64 = (-2f64) * __t135;
            let __t137: ::routh::__private::f64 = __t136 - __t133;
            let __t138: ::routh::__private::f64 = __v3 * __t137;
            let __t139: ::routh::__private::f64 = __t55 + __t138;
            let __t140: ::routh::__private::f64 = __v7 * __t139;
            let __t143: ::routh::__private::f64 = __t97 * __t127;
            let __t147: ::routh::__private::f64 = __t29 * __t54;
            let __t149: ::routh::__private::f64 = __t53 * __t143;
            let __t150: ::routh::__private::f64 = (-2f64) * __t149;
            let __t151: ::routh::__private::f64 = __t150 - __t147;
            let __t152: ::routh::__private::f64 = __v3 * __t151;
            let __t153: ::routh::__private::f64 = __v7 * __t152;
            let __t155: ::routh::__private::f64 = __t48 * __t127;
            let __t159: ::routh::__private::f64 = __t15 * __t54;
            let __t161: ::routh::__private::f64 = __t53 * __t155;
            let __t162: ::routh::__private::f64 = (-2f64) * __t161;
            let __t163: ::routh::__private::f64 = __t162 - __t159;
            let __t164: ::routh::__private::f64 = __v3 * __t163;
            let __t165: ::routh::__private::f64 = __v7 * __t164;
            let __t166: ::routh::__private::f64 = __v4 * __t137;
            let __t167: ::routh::__private::f64 = __v7 * __t166;
            let __t168: ::routh::__private::f64 = __v4 * __t151;
            let __t169: ::routh::__private::f64 = __t55 + __t168;
            let __t170: ::routh::__private::f64 = __v7 * __t169;
            let __t171: ::routh::__private::f64 = __v4 * __t163;
            let __t172: ::routh::__private::f64 = __v7 * __t171;
            let __t173: ::routh::__private::f64 = __v5 * __t137;
            let __t174: ::routh::__private::f64 = __v8 * __t173;
            let __t175: ::routh::__private::f64 = __v5 * __t151;
            let __t176: ::routh::__private::f64 = __v8 * __t175;
            let __t177: ::routh::__private::f64 = __v5 * __t163;
            let __t178: ::routh::__private::f64 = __t55 + __t177;
            let __t179: ::routh::__private::f64 = __v8 * __t178;
            let __t180: ::routh::__private::f64 = __t78 * __t137;
            let __t181: ::routh::__private::f64 = __t55 * __t140;
            let __t182: ::routh::__private::f64 = __t180 + __t181;
            let __t183: ::routh::__private::f64 = __t78 * __t151;
            let __t184: ::routh::__private::f64 = __t55 * __t153;
            let __t185: ::routh::__private::f64 = __t183 + __t184;
            let __t186: ::routh::__private::f64 = __t78 * __t163;
            let __t187: ::routh::__private::f64 = __t55 * __t165;
            let __t188: ::routh::__private::f64 = __t186 + __t187;
            let __t189: ::routh::__private::f64 = __t81 * __t151;
            let __t190: ::routh::__private::f64 = __t55 * __t170;
            let __t191: ::routh::__private::f64 = __t189 + __t190;
            let __t192: ::routh::__private::f64 = __t81 * __t163;
            let __t193: ::routh::__private::f64 = __t55 * __t172;
            let __t194: ::routh::__private::f64 = __t192 + __t193;
            let __t195: ::routh::__private::f64 = __t72 * __t163;
            let __t196: ::routh::__private::f64 = __t55 * __t179;
            let __t197: ::routh::__private::f64 = __t195 + __t196;
            ::routh::__private::RouthBundle {
                routhian: __t61,
                psi_dot: __t55,
                dr_domega: ::routh::__private::Vector3::new(__t78, __t81, __t72),
                dr_dgamma: ::routh::__private::Vector3::new(__t84, __t85, __t87),
                dr_dp: __t88,
                d2r_domega2: ::routh::__private::Matrix3::new(
                    __t96,
                    __t104,
                    __t111,
                    __t104,
                    __t115,
                    __t119,
                    __t111,
                    __t119,
                    __t123,
                ),
                d2r_domega_dgamma: ::routh::__private::Matrix3::new(
                    __t140,
                    __t153,
                    __t165,
                    __t167,
                    __t170,
                    __t172,
                    __t174,
                    __t176,
                    __t179,
                ),
                d2r_dgamma2: ::routh::__private::Matrix3::new(
                    __t182,
                    __t185,
                    __t188,
                    __t185,
                    __t191,
                    __t194,
                    __t188,
                    __t194,
                    __t197,
                ),
            }
        }
        #[inline]
        fn gyroscopic_system(
            &self,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::GyroscopicSystem {
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __v9: ::routh::__private::f64 = self.mgl;
            let __t44: ::routh::__private::f64 = __v3 * __v3;
            let __t45: ::routh::__private::f64 = __v4 * __v4;
            let __t46: ::routh::__private::f64 = __t44 + __t45;
            let __t47: ::routh::__private::f64 = __v7 * __t46;
            let __t48: ::routh::__private::f64 = __v5 * __v8;
            let __t49: ::routh::__private::f64 = __v5 * __t48;
            let __t50: ::routh::__private::f64 = __t47 + __t49;
            let __t54: ::routh::__private::f64 = 1.0f64 / __t50;
            let __t89: ::routh::__private::f64 = __v3 * __v7;
            let __t91: ::routh::__private::f64 = __t54 * __t89;
            let __t93: ::routh::__private::f64 = __v3 * __t91;
            let __t95: ::routh::__private::f64 = 1f64 - __t93;
            let __t96: ::routh::__private::f64 = __v7 * __t95;
            let __t97: ::routh::__private::f64 = __v4 * __v7;
            let __t99: ::routh::__private::f64 = __t54 * __t97;
            let __t101: ::routh::__private::f64 = __v3 * __t99;
            let __t103: ::routh::__private::f64 = __v7 * __t101;
            let __t104: ::routh::__private::f64 = -__t103;
            let __t106: ::routh::__private::f64 = __t48 * __t54;
            let __t108: ::routh::__private::f64 = __v3 * __t106;
            let __t110: ::routh::__private::f64 = __v7 * __t108;
            let __t111: ::routh::__private::f64 = -__t110;
            let __t112: ::routh::__private::f64 = __v4 * __t99;
            let __t114: ::routh::__private::f64 = 1f64 - __t112;
            let __t115: ::routh::__private::f64 = __v7 * __t114;
            let __t116: ::routh::__private::f64 = __v4 * __t106;
            let __t118: ::routh::__private::f64 = __v7 * __t116;
            let __t119: ::routh::__private::f64 = -__t118;
            let __t120: ::routh::__private::f64 = __v5 * __t106;
            let __t122: ::routh::__private::f64 = 1f64 - __t120;
            let __t123: ::routh::__private::f64 = __v8 * __t122;
            let __t126: ::routh::__private::f64 = __t50 * __t50;
            let __t127: ::routh::__private::f64 = 1.0f64 / __t126;
            let __t128: ::routh::__private::f64 = __t89 * __t127;
            let __t143: ::routh::__private::f64 = __t97 * __t127;
            let __t155: ::routh::__private::f64 = __t48 * __t127;
            let __t198: ::routh::__private::f64 = __v6 * __t54;
            let __t204: ::routh::__private::f64 = __v3 * __t198;
            let __t205: ::routh::__private::f64 = __v4 * __t198;
            let __t206: ::routh::__private::f64 = __v5 * __t198;
            let __t211: ::routh::__private::f64 = __v8 * __t206;
            let __t217: ::routh::__private::f64 = __v7 * __t204;
            let __t220: ::routh::__private::f64 = __v7 * __t205;
            let __t223: ::routh::__private::f64 = __t198 * __t217;
            let __t224: ::routh::__private::f64 = __t198 * __t220;
            let __t225: ::routh::__private::f64 = __t198 * __t211;
            let __t226: ::routh::__private::f64 = __t225 - __v9;
            let __t228: ::routh::__private::f64 = __v6 * __t128;
            let __t230: ::routh::__private::f64 = __v3 * __t228;
            let __t231: ::routh::__private::f64 = (-2f64) * __t230;
            let __t232: ::routh::__private::f64 = __t198 + __t231;
            let __t233: ::routh::__private::f64 = __v7 * __t232;
            let __t234: ::routh::__private::f64 = __v6 * __t143;
            let __t236: ::routh::__private::f64 = __v3 * __t234;
            let __t238: ::routh::__private::f64 = __v7 * __t236;
            let __t240: ::routh::__private::f64 = __v6 * __t155;
            let __t242: ::routh::__private::f64 = __v3 * __t240;
            let __t244: ::routh::__private::f64 = __v7 * __t242;
            let __t246: ::routh::__private::f64 = __v4 * __t228;
            let __t248: ::routh::__private::f64 = __v7 * __t246;
            let __t250: ::routh::__private::f64 = __v4 * __t234;
            let __t251: ::routh::__private::f64 = (-2f64) * __t250;
            let __t252: ::routh::__private::f64 = __t198 + __t251;
            let __t253: ::routh::__private::f64 = __v7 * __t252;
            let __t254: ::routh::__private::f64 = __v4 * __t240;
            let __t256: ::routh::__private::f64 = __v7 * __t254;
            let __t258: ::routh::__private::f64 = __v5 * __t228;
            let __t260: ::routh::__private::f64 = __v8 * __t258;
            let __t262: ::routh::__private::f64 = __v5 * __t234;
            let __t264: ::routh::__private::f64 = __v8 * __t262;
            let __t266: ::routh::__private::f64 = __v5 * __t240;
            let __t267: ::routh::__private::f64 = (-2f64) * __t266;
            let __t268: ::routh::__private::f64 = __t198 + __t267;
            let __t269: ::routh::__private::f64 = __v8 * __t268;
            let __t270: ::routh::__private::f64 = __t217 * __t228;
            let __t271: ::routh::__private::f64 = (-2f64) * __t270;
            let __t272: ::routh::__private::f64 = __t198 * __t233;
            let __t273: ::routh::__private::f64 = __t271 + __t272;
            let __t274: ::routh::__private::f64 = __t217 * __t234;
            let __t275: ::routh::__private::f64 = (-2f64) * __t274;
            let __t276: ::routh::__private::f64 = __t198 * __t238;
            let __t277: ::routh::__private::f64 = (-2f64) * __t276;
            let __t278: ::routh::__private::f64 = __t275 + __t277;
            let __t279: ::routh::__private::f64 = __t217 * __t240;
            let __t280: ::routh::__private::f64 = (-2f64) * __t279;
            let __t281: ::routh::__private::f64 = __t198 * __t244;
            let __t282: ::routh::__private::f64 = (-2f64) * __t281;
            let __t283: ::routh::__private::f64 = __t280 + __t282;
            let __t284: ::routh::__private::f64 = __t220 * __t234;
            let __t285: ::routh::__private::f64 = (-2f64) * __t284;
            let __t286: ::routh::__private::f64 = __t198 * __t253;
            let __t287: ::routh::__private::f64 = __t285 + __t286;
            let __t288: ::routh::__private::f64 = __t220 * __t240;
            let __t289: ::routh::__private::f64 = (-2f64) * __t288;
            let __t290: ::routh::__private::f64 = __t198 * __t256;
            let __t291: ::routh::__private::f64 = (-2f64) * __t290;
            let __t292: ::routh::__private::f64 = __t289 + __t291;
            let __t293: ::routh::__private::f64 = __t211 * __t240;
            let __t294: ::routh::__private::f64 = (-2f64) * __t293;
            let __t295: ::routh::__private::f64 = __t198 * __t269;
            let __t296: ::routh::__private::f64 = __t294 + __t295;
            let __t304: ::routh::__private::f64 = __v5 * __t238;
            let __t305: ::routh::__private::f64 = (-2f64) * __t304;
            let __t306: ::routh::__private::f64 = __v4 * __t244;
            let __t307: ::routh::__private::f64 = (-2f64) * __t306;
            let __t308: ::routh::__private::f64 = 2f64 * __t306;
            let __t309: ::routh::__private::f64 = __t305 + __t308;
            let __t310: ::routh::__private::f64 = __v5 * __t233;
            let __t312: ::routh::__private::f64 = __v3 * __t244;
            let __t313: ::routh::__private::f64 = (-2f64) * __t312;
            let __t314: ::routh::__private::f64 = __t313 - __t310;
            let __t315: ::routh::__private::f64 = __v4 * __t233;
            let __t316: ::routh::__private::f64 = __v3 * __t238;
            let __t317: ::routh::__private::f64 = (-2f64) * __t316;
            let __t318: ::routh::__private::f64 = 2f64 * __t316;
            let __t319: ::routh::__private::f64 = __t315 + __t318;
            let __t320: ::routh::__private::f64 = __v5 * __t253;
            let __t321: ::routh::__private::f64 = __v4 * __t256;
            let __t322: ::routh::__private::f64 = (-2f64) * __t321;
            let __t323: ::routh::__private::f64 = 2f64 * __t321;
            let __t324: ::routh::__private::f64 = __t320 + __t323;
            let __t325: ::routh::__private::f64 = __v5 * __t248;
            let __t326: ::routh::__private::f64 = (-2f64) * __t325;
            let __t327: ::routh::__private::f64 = 2f64 * __t325;
            let __t328: ::routh::__private::f64 = __v3 * __t256;
            let __t329: ::routh::__private::f64 = (-2f64) * __t328;
            let __t330: ::routh::__private::f64 = __t327 + __t329;
            let __t331: ::routh::__private::f64 = __v4 * __t248;
            let __t332: ::routh::__private::f64 = (-2f64) * __t331;
            let __t333: ::routh::__private::f64 = __v3 * __t253;
            let __t335: ::routh::__private::f64 = __t332 - __t333;
            let __t336: ::routh::__private::f64 = __v5 * __t264;
            let __t337: ::routh::__private::f64 = (-2f64) * __t336;
            let __t338: ::routh::__private::f64 = __v4 * __t269;
            let __t340: ::routh::__private::f64 = __t337 - __t338;
            let __t341: ::routh::__private::f64 = __v5 * __t260;
            let __t342: ::routh::__private::f64 = (-2f64) * __t341;
            let __t343: ::routh::__private::f64 = 2f64 * __t341;
            let __t344: ::routh::__private::f64 = __v3 * __t269;
            let __t345: ::routh::__private::f64 = __t343 + __t344;
            let __t346: ::routh::__private::f64 = __v4 * __t260;
            let __t347: ::routh::__private::f64 = (-2f64) * __t346;
            let __t348: ::routh::__private::f64 = __v3 * __t264;
            let __t349: ::routh::__private::f64 = (-2f64) * __t348;
            let __t350: ::routh::__private::f64 = 2f64 * __t348;
            let __t351: ::routh::__private::f64 = __t347 + __t350;
            let __t352: ::routh::__private::f64 = 2f64 * __t304;
            let __t353: ::routh::__private::f64 = __t307 + __t352;
            let __t355: ::routh::__private::f64 = __t322 - __t320;
            let __t356: ::routh::__private::f64 = 2f64 * __t336;
            let __t357: ::routh::__private::f64 = __t338 + __t356;
            let __t358: ::routh::__private::f64 = 2f64 * __t312;
            let __t359: ::routh::__private::f64 = __t310 + __t358;
            let __t360: ::routh::__private::f64 = 2f64 * __t328;
            let __t361: ::routh::__private::f64 = __t326 + __t360;
            let __t363: ::routh::__private::f64 = __t342 - __t344;
            let __t365: ::routh::__private::f64 = __t317 - __t315;
            let __t366: ::routh::__private::f64 = 2f64 * __t331;
            let __t367: ::routh::__private::f64 = __t333 + __t366;
            let __t368: ::routh::__private::f64 = 2f64 * __t346;
            let __t369: ::routh::__private::f64 = __t349 + __t368;
            let __t370: ::routh::__private::f64 = __t309 + __t353;
            let __t371: ::routh::__private::f64 = 0.5f64 * __t370;
            let __t372: ::routh::__private::f64 = __t314 + __t355;
            let __t373: ::routh::__private::f64 = __t211 + __t372;
            let __t374: ::routh::__private::f64 = 0.5f64 * __t373;
            let __t375: ::routh::__private::f64 = __t319 + __t357;
            let __t376: ::routh::__private::f64 = __t375 - __t220;
            let __t377: ::routh::__private::f64 = 0.5f64 * __t376;
            let __t378: ::routh::__private::f64 = __t324 + __t359;
            let __t379: ::routh::__private::f64 = __t378 - __t211;
            let __t380: ::routh::__private::f64 = 0.5f64 * __t379;
            let __t381: ::routh::__private::f64 = __t330 + __t361;
            let __t382: ::routh::__private::f64 = 0.5f64 * __t381;
            let __t383: ::routh::__private::f64 = __t335 + __t363;
            let __t384: ::routh::__private::f64 = __t217 + __t383;
            let __t385: ::routh::__private::f64 = 0.5f64 * __t384;
            let __t386: ::routh::__private::f64 = __t340 + __t365;
            let __t387: ::routh::__private::f64 = __t220 + __t386;
            let __t388: ::routh::__private::f64 = 0.5f64 * __t387;
            let __t389: ::routh::__private::f64 = __t345 + __t367;
            let __t390: ::routh::__private::f64 = __t389 - __t217;
            let __t391: ::routh::__private::f64 = 0.5f64 * __t390;
            let __t392: ::routh::__private::f64 = __t351 + __t369;
            let __t393: ::routh::__private::f64 = 0.5f64 * __t392;
            let __t394: ::routh::__private::f64 = __v3 * __t223;
            let __t395: ::routh::__private::f64 = __v4 * __t224;
            let __t396: ::routh::__private::f64 = __v5 * __t226;
            let __t397: ::routh::__private::f64 = __t394 + __t395;
            let __t398: ::routh::__private::f64 = __t396 + __t397;
            let __t400: ::routh::__private::f64 = __t398 - __t273;
            let __t404: ::routh::__private::f64 = __t398 - __t287;
            let __t407: ::routh::__private::f64 = __t398 - __t296;
            let __t408: ::routh::__private::f64 = __v5 * __t278;
            let __t410: ::routh::__private::f64 = __v4 * __t283;
            let __t412: ::routh::__private::f64 = __t410 - __t408;
            let __t413: ::routh::__private::f64 = __v5 * __t404;
            let __t414: ::routh::__private::f64 = __v4 * __t292;
            let __t416: ::routh::__private::f64 = __t413 + __t414;
            let __t417: ::routh::__private::f64 = __v5 * __t292;
            let __t419: ::routh::__private::f64 = __v4 * __t407;
            let __t421: ::routh::__private::f64 = __t417 + __t419;
            let __t423: ::routh::__private::f64 = __v5 * __t400;
            let __t425: ::routh::__private::f64 = __v3 * __t283;
            let __t427: ::routh::__private::f64 = __t423 + __t425;
            let __t429: ::routh::__private::f64 = __v3 * __t292;
            let __t431: ::routh::__private::f64 = __t408 - __t429;
            let __t432: ::routh::__private::f64 = __v5 * __t283;
            let __t434: ::routh::__private::f64 = __v3 * __t407;
            let __t435: ::routh::__private::f64 = __t432 + __t434;
            let __t436: ::routh::__private::f64 = __v4 * __t400;
            let __t437: ::routh::__private::f64 = __v3 * __t278;
            let __t439: ::routh::__private::f64 = __t436 + __t437;
            let __t440: ::routh::__private::f64 = __v4 * __t278;
            let __t442: ::routh::__private::f64 = __v3 * __t404;
            let __t444: ::routh::__private::f64 = __t440 + __t442;
            let __t446: ::routh::__private::f64 = __t429 - __t410;
            let __t447: ::routh::__private::f64 = __v5 * __t416;
            let __t448: ::routh::__private::f64 = __v4 * __t421;
            let __t450: ::routh::__private::f64 = __t447 + __t448;
            let __t451: ::routh::__private::f64 = __v5 * __t412;
            let __t453: ::routh::__private::f64 = __v3 * __t421;
            let __t455: ::routh::__private::f64 = __t451 + __t453;
            let __t456: ::routh::__private::f64 = -__t455;
            let __t457: ::routh::__private::f64 = __v4 * __t412;
            let __t458: ::routh::__private::f64 = __v3 * __t416;
            let __t460: ::routh::__private::f64 = __t457 - __t458;
            let __t461: ::routh::__private::f64 = __v5 * __t431;
            let __t462: ::routh::__private::f64 = __v4 * __t435;
            let __t464: ::routh::__private::f64 = __t461 - __t462;
            let __t465: ::routh::__private::f64 = __v5 * __t427;
            let __t467: ::routh::__private::f64 = __v3 * __t435;
            let __t468: ::routh::__private::f64 = __t465 + __t467;
            let __t469: ::routh::__private::f64 = __v4 * __t427;
            let __t471: ::routh::__private::f64 = __v3 * __t431;
            let __t473: ::routh::__private::f64 = __t469 + __t471;
            let __t474: ::routh::__private::f64 = -__t473;
            let __t475: ::routh::__private::f64 = __v5 * __t444;
            let __t477: ::routh::__private::f64 = __v4 * __t446;
            let __t479: ::routh::__private::f64 = __t475 + __t477;
            let __t480: ::routh::__private::f64 = -__t479;
            let __t481: ::routh::__private::f64 = __v5 * __t439;
            let __t483: ::routh::__private::f64 = __v3 * __t446;
            let __t484: ::routh::__private::f64 = __t483 - __t481;
            let __t485: ::routh::__private::f64 = __v4 * __t439;
            let __t486: ::routh::__private::f64 = __v3 * __t444;
            let __t488: ::routh::__private::f64 = __t485 + __t486;
            ::routh::__private::GyroscopicSystem {
                a: ::routh::__private::Matrix3::new(
                    __t96,
                    __t104,
                    __t111,
                    __t104,
                    __t115,
                    __t119,
                    __t111,
                    __t119,
                    __t123,
                ),
                g: ::routh::__private::Matrix3::new(
                    __t371,
                    __t374,
                    __t377,
                    __t380,
                    __t382,
                    __t385,
                    __t388,
                    __t391,
                    __t393,
                ),
                c: ::routh::__private::Matrix3::new(
                    __t450,
                    __t456,
                    __t460,
                    __t464,
                    __t468,
                    __t474,
                    __t480,
                    __t484,
                    __t488,
                ),
            }
        }
    }
};
